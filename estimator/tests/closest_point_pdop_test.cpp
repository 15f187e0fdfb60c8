#include "anchorbench/estimator/closest_point_pdop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "anchorbench/estimator/pdop.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

// Eq. (4) computed directly: G~ built row by row around the shortest range, row j removed.
// The index of the shortest range: the closest point p_C.
std::size_t Closest(const std::vector<double>& d) {
  return static_cast<std::size_t>(std::min_element(d.begin(), d.end()) - d.begin());
}

double DirectClosestPointPdop(const std::vector<Eigen::Vector3d>& p, const std::vector<double>& d) {
  const std::size_t j = Closest(d);
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (k == j) continue;
    const Eigen::Vector3d row = (p[k] - p[j]) / d[k];
    information += row * row.transpose();
  }
  return d.size() < 4 ? std::numeric_limits<double>::infinity() : PdopFromInformation(information);
}

TEST(ClosestPointPdop, StreamingMatchesDirectEq4OverRandomSequences) {
  int closest_point_changes = 0;
  for (int sequence = 0; sequence < 50; ++sequence) {
    auto rng = testing::TestStream(sequence);
    // Far from the world origin, as a tunnel anchor 10 km down the line would be.
    const double offset_y = 50.0 * rng.Uniform();  // sequenced: GCC's order, the test's first data
    const double offset_x = 1e4 * rng.Uniform();
    const Eigen::Vector3d offset(offset_x, offset_y, 3.0);
    const Eigen::Vector3d p_anchor = offset + Eigen::Vector3d(0, 0, 4);
    ClosestPointPdop streaming;
    std::vector<Eigen::Vector3d> p;
    std::vector<double> d;
    double previous_min = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 300; ++k) {
      // A pass by the anchor: ranges shrink, then grow, so p_C moves many times.
      const Eigen::Vector3d tag = offset + Eigen::Vector3d(-30.0 + 0.2 * k, 3.0 * rng.Uniform(-1, 1),
                                                           1.5 * rng.Uniform(-1, 1));
      const double range = (tag - p_anchor).norm() + 0.05 * rng.Normal();
      streaming.Add(tag, range);
      p.push_back(tag);
      d.push_back(range);
      if (range < previous_min) {
        previous_min = range;
        ++closest_point_changes;
      }
      const double direct = DirectClosestPointPdop(p, d);
      const double online = streaming.Value();
      if (std::isinf(direct)) {
        EXPECT_TRUE(std::isinf(online)) << "sample " << k;
      } else {
        EXPECT_NEAR(online, direct, 1e-9 * direct) << "sequence " << sequence << " sample " << k;
      }
    }
  }
  EXPECT_GT(closest_point_changes, 50 * 20);  // the closest point did change along the way
}

// The bias column: [G~ | 1] built directly about the final closest point, all N rows (the row of
// p_C is zero in G~ but one in the bias column).
double DirectClosestPointBiasAwareDop(const std::vector<Eigen::Vector3d>& p, const std::vector<double>& d) {
  const std::size_t j = Closest(d);
  Eigen::Matrix4d information = Eigen::Matrix4d::Zero();
  for (std::size_t k = 0; k < d.size(); ++k) {
    Eigen::Vector4d row;
    row << (p[k] - p[j]) / d[k], 1.0;
    information += row * row.transpose();
  }
  return std::sqrt(information.inverse().topLeftCorner<3, 3>().trace());
}

TEST(ClosestPointPdop, StreamingBiasAwareDopMatchesTheDirect4ColumnMatrix) {
  for (int sequence = 0; sequence < 20; ++sequence) {
    auto rng = testing::TestStream(100 + sequence);
    const Eigen::Vector3d p_anchor(5e3, 10.0, 4.0);
    ClosestPointPdop streaming;
    std::vector<Eigen::Vector3d> p;
    std::vector<double> d;
    for (int k = 0; k < 200; ++k) {
      const double u = rng.Uniform(-1, 1), v = rng.Uniform(-1, 1);  // sequenced draws
      const Eigen::Vector3d tag = p_anchor + Eigen::Vector3d(-20.0 + 0.2 * k, 4.0 * u, -3.0 + v);
      const double range = (tag - p_anchor).norm();
      streaming.Add(tag, range);
      p.push_back(tag);
      d.push_back(range);
      if (k < 10) continue;
      const double direct = DirectClosestPointBiasAwareDop(p, d);
      EXPECT_NEAR(streaming.BiasAwareValue(), direct, 1e-7 * direct) << "sequence " << sequence << " sample " << k;
      EXPECT_GE(streaming.BiasAwareValue(), streaming.Value() * (1 - 1e-12));  // a column more: never better
    }
  }
}

TEST(ClosestPointPdop, InfiniteNotNanWhenUndefined) {
  ClosestPointPdop pdop;
  EXPECT_TRUE(std::isinf(pdop.Value()));
  for (int k = 0; k < 3; ++k) pdop.Add(Eigen::Vector3d(k, k * k, 1.0), 5.0 + k);
  EXPECT_TRUE(std::isinf(pdop.Value()));  // 3 samples: G~ has only 2 rows
  ClosestPointPdop collinear;
  for (int k = 0; k < 100; ++k) collinear.Add(Eigen::Vector3d(0.1 * k, 2.0, 1.0), 10.0 + 0.01 * k);
  EXPECT_TRUE(std::isinf(collinear.Value()));  // rank 1: a straight line
  EXPECT_TRUE(std::isinf(collinear.BiasAwareValue()));
  EXPECT_TRUE(std::isinf(pdop.BiasAwareValue()));
}

}  // namespace
}  // namespace anchorbench::estimator
