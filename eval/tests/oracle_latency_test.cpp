// The ideal region's time: the earliest sample from which the Cramer-Rao region of the certificate's
// confidence lies within D.
#include "anchorbench/eval/oracle_latency.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/eval/true_geometry.hpp"

namespace anchorbench::eval {
namespace {

// A tag circling 10 m from the anchor at heights that alternate +-2 m, 10 samples per second.
struct Circling {
  std::vector<Eigen::Vector3d> p_world_tag;
  std::vector<double> t_s;
};
Circling Circle(int samples) {
  Circling c;
  for (int k = 0; k < samples; ++k) {
    const double angle = 0.05 * k;
    c.p_world_tag.emplace_back(10.0 * std::cos(angle), 10.0 * std::sin(angle), k % 2 == 0 ? 2.0 : -2.0);
    c.t_s.push_back(0.1 * k);
  }
  return c;
}

bool Within(const Circling& c, std::size_t samples, double sigma_m, double d_m) {
  TrueGeometry geometry(Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < samples; ++k) geometry.Add(c.p_world_tag[k]);
  return estimator::ChiSquare3Quantile(0.99) * sigma_m * sigma_m / geometry.BiasAwareLeastInformation() <= d_m * d_m;
}

TEST(IdealRegion, LeastInformationIsTheInverseOfTheCovariancesLargestVariance) {
  const Circling c = Circle(200);
  TrueGeometry geometry(Eigen::Vector3d::Zero());
  for (const Eigen::Vector3d& p : c.p_world_tag) geometry.Add(p);
  // BiasAwareDop^2 is the trace of the covariance: at least its largest variance, at most 3 times it.
  const double largest = 1.0 / geometry.BiasAwareLeastInformation();
  EXPECT_LE(largest, std::pow(geometry.BiasAwareDop(), 2) + 1e-9);
  EXPECT_GE(3.0 * largest, std::pow(geometry.BiasAwareDop(), 2) - 1e-9);
  TrueGeometry none(Eigen::Vector3d::Zero());
  EXPECT_EQ(none.BiasAwareLeastInformation(), 0.0);
}

TEST(IdealRegion, TimeIsTheFirstSampleWhoseRegionLiesWithinD) {
  const Circling c = Circle(2000);
  const double sigma_m = 0.3, d_m = 0.75;
  const std::optional<double> t = IdealRegionTime(c.p_world_tag, c.t_s, Eigen::Vector3d::Zero(), d_m, {sigma_m, 0.99});
  ASSERT_TRUE(t.has_value());
  // A scan: the first sample count whose region fits; the one before it does not.
  std::size_t first = 1;
  while (!Within(c, first, sigma_m, d_m)) ++first;
  EXPECT_DOUBLE_EQ(*t, c.t_s[first - 1]);
  EXPECT_GT(first, 3u);
  // Noisier ranges need more data; a tighter confidence does too.
  const std::optional<double> noisier =
      IdealRegionTime(c.p_world_tag, c.t_s, Eigen::Vector3d::Zero(), d_m, {2.0 * sigma_m, 0.99});
  ASSERT_TRUE(noisier.has_value());
  EXPECT_GT(*noisier, *t);
  EXPECT_GT(*IdealRegionTime(c.p_world_tag, c.t_s, Eigen::Vector3d::Zero(), d_m, {sigma_m, 0.999}), *t);
}

TEST(IdealRegion, NoTimeWhereTheDataNeverGetThere) {
  const Circling c = Circle(2000);
  EXPECT_FALSE(IdealRegionTime(c.p_world_tag, c.t_s, Eigen::Vector3d::Zero(), 0.75, {50.0, 0.99}).has_value());
  // A path at the anchor's height: the height trades off against the bias, no region is bounded.
  Circling flat = c;
  for (Eigen::Vector3d& p : flat.p_world_tag) p.z() = 0.0;
  EXPECT_FALSE(IdealRegionTime(flat.p_world_tag, flat.t_s, Eigen::Vector3d::Zero(), 0.75, {0.01, 0.99}).has_value());
  EXPECT_FALSE(IdealRegionTime({}, {}, Eigen::Vector3d::Zero(), 0.75, {0.1, 0.99}).has_value());
}

}  // namespace
}  // namespace anchorbench::eval
