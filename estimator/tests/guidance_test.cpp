// Guidance (guidance.hpp): the forecast of the certificate's region from samples at a candidate
// position, O(1) per candidate, is the region rebuilt from the samples with the candidate's; it
// prefers positions that see what the path does not; and the certified initializer offers it.
#include "anchorbench/estimator/guidance.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/estimator/consistency_filter.hpp"
#include "anchorbench/estimator/guide.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

const Eigen::Vector3d kGuidedAnchor(15.0, 4.0, 0.7);  // beside the loop, 0.2 m above its floor: its height hardly seen

std::vector<Eigen::Vector3d> FlatLoop(int n) {  // a robot's loop on the floor, 0.5 m up, within 2 cm
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < n; ++k) {
    const double t = 0.1 * k;
    p.emplace_back(3.0 + 5.0 * std::cos(0.2 * t), 4.0 + 4.0 * std::sin(0.13 * t), 0.5 + 0.02 * std::sin(0.7 * t));
  }
  return p;
}

RegionBasis Basis() {
  RegionBasis basis;
  basis.p_world_anchor = kGuidedAnchor;
  basis.noise_variance_m2 = 0.05 * 0.05;
  basis.region_chi2 = ChiSquare3Quantile(0.99);
  basis.accuracy_m = 0.75;
  basis.covariance.travel_bias = false;
  return basis;
}

// The O(1) update is the O(N) rebuild with the candidate's samples appended: one tag; two tags with
// their offsets among the unknowns; two tags with a link term for their offsets instead.
TEST(Guidance, TheForecastIsTheRegionRebuiltWithTheCandidatesSamples) {
  const std::vector<Eigen::Vector3d> path = FlatLoop(400);
  const Eigen::Vector3d candidate(6.0, 1.0, 2.5);
  for (const int mode : {0, 1, 2}) {
    RegionBasis basis = Basis();
    basis.tag_offsets = mode == 1;
    if (mode == 1) basis.covariance.link_offset_m = 0.0;  // estimated: not a link term too (as the certificate)
    std::vector<int> tags(path.size());
    for (std::size_t k = 0; k < tags.size(); ++k) tags[k] = mode > 0 ? static_cast<int>(k % 2) : 0;
    const RegionForecast forecast(basis, path, tags);
    std::vector<Eigen::Vector3d> more = path;
    std::vector<int> more_tags = tags;
    for (int k = 0; k < 30; ++k) {
      more.push_back(candidate);
      more_tags.push_back(tags.back());
    }
    const double rebuilt = RegionForecast(basis, more, more_tags).region_m();
    EXPECT_NEAR(forecast.RegionAfter(candidate, 30.0), rebuilt, 1e-9 * rebuilt) << mode;
    EXPECT_LT(rebuilt, forecast.region_m()) << mode;
  }
}

// A flat path leaves the height to the region: ranging from above the floor closes it, ranging
// from the floor hardly does, and the ranking puts the high candidates first.
TEST(Guidance, OnAFlatPathRangingFromAboveTheFloorClosesTheRegion) {
  const std::vector<Eigen::Vector3d> path = FlatLoop(600);
  const RegionForecast forecast(Basis(), path, std::vector<int>(path.size(), 0));
  ASSERT_GT(forecast.region_m(), 0.75);
  const Eigen::Vector3d on_floor(9.0, 4.0, 0.5), above(9.0, 4.0, 2.5);
  EXPECT_LT(forecast.RegionAfter(above, 50.0), 0.5 * forecast.RegionAfter(on_floor, 50.0));
  const std::vector<Eigen::Vector3d> grid = CandidateGrid(on_floor, 2.0, 2);
  ASSERT_EQ(grid.size(), 125u);
  const std::vector<CandidateForecast> best = forecast.Rank(grid, 50.0, 5);
  ASSERT_EQ(best.size(), 5u);
  for (std::size_t i = 0; i < best.size(); ++i) {
    EXPECT_GT(best[i].p_world_candidate.z(), 1.0);
    if (i > 0) {
      EXPECT_LE(best[i - 1].region_m, best[i].region_m);
    }
  }
}

// The samples to certify are the fewest that bring the region within D; where the model error
// alone keeps it wider than D, none do.
TEST(Guidance, SamplesToCertifyAreTheFewestThatReachD) {
  const std::vector<Eigen::Vector3d> path = FlatLoop(600);
  const RegionForecast forecast(Basis(), path, std::vector<int>(path.size(), 0));
  const Eigen::Vector3d above(9.0, 4.0, 2.5);
  const double samples = forecast.SamplesToCertify(above);
  ASSERT_TRUE(std::isfinite(samples));
  ASSERT_GT(samples, 0.0);
  EXPECT_LE(forecast.RegionAfter(above, samples), 0.75);
  EXPECT_GT(forecast.RegionAfter(above, samples - 1.0), 0.75);

  RegionBasis rough = Basis();
  rough.covariance.model_error_m = 1.0;  // a range error no data average away
  const RegionForecast floor(rough, path, std::vector<int>(path.size(), 0));
  EXPECT_EQ(floor.SamplesToCertify(above), std::numeric_limits<double>::infinity());
}

std::vector<RangeSample> FlatSamples(double seconds) {
  auto rng = testing::TestStream(5);
  std::vector<RangeSample> samples;
  const std::vector<Eigen::Vector3d> path = FlatLoop(static_cast<int>(10.0 * seconds));
  for (std::size_t k = 0; k < path.size(); ++k) {
    samples.push_back({0.1 * static_cast<double>(k), 0, 7, (path[k] - kGuidedAnchor).norm() + 0.1 + 0.05 * rng.Normal(), path[k]});
  }
  return samples;
}

AnchorInitializer CertifiedChain(int anchor_id) {
  auto solver = std::make_shared<AnchorSolver>();
  return AnchorInitializer(anchor_id, InitializerOptions{}, std::make_unique<ConsistencyFilter>(),
                           std::make_unique<CertifiedTrigger>(solver, AnchorSolverOptions{}, CertificateOptions{},
                                                              HeightCheckOptions{}, TagBiasOptions{},
                                                              [](double s, double slack) { return ConsistencyFilter().TravelBias(s, slack); },
                                                              SolveCadence(10, 1.1)),
                           solver);
}

// The certified initializer offers a forecast once it has judged an estimate, from the same
// numbers it judged (its region within a factor of the judgement's); the paper's trigger has none.
TEST(Guidance, TheCertifiedInitializerOffersAForecastAfterAnEvaluation) {
  AnchorInitializer certified = CertifiedChain(7);
  EXPECT_FALSE(certified.Forecast());
  for (const RangeSample& s : FlatSamples(60.0)) EXPECT_FALSE(certified.Feed(s).event);
  const std::optional<Judgement> judged = certified.why_not();
  ASSERT_TRUE(judged);
  const std::optional<RegionForecast> forecast = certified.Forecast();
  ASSERT_TRUE(forecast);
  ASSERT_TRUE(std::isfinite(judged->region_m));
  EXPECT_GT(forecast->region_m(), 0.5 * judged->region_m);
  EXPECT_LT(forecast->region_m(), 2.0 * judged->region_m);

  AnchorInitializer paper(7, InitializerOptions{}, std::make_unique<ConsistencyFilter>(),
                          std::make_unique<ClosestPointPdopTrigger>(1.0), std::make_shared<AnchorSolver>());
  for (const RangeSample& s : FlatSamples(10.0)) paper.Feed(s);
  EXPECT_FALSE(paper.Forecast());
}

// A front end's guidance: every waiting anchor of a certified chain, its best candidates ranked
// around its last tag position (the default grid), with the seconds to certify at the link's rate.
TEST(Guidance, AFrontEndGuidesEveryWaitingAnchor) {
  FrontEnd front_end([](int anchor_id) {
    std::vector<AnchorInitializer> chains;
    chains.push_back(CertifiedChain(anchor_id));
    return chains;
  });
  for (const RangeSample& s : FlatSamples(60.0)) front_end.AddSample(s);
  GuideRequest request;
  request.range_rate_hz = 20.0;
  const std::vector<AnchorGuidance> guided = Guide(front_end, request);
  ASSERT_EQ(guided.size(), 1u);
  EXPECT_EQ(guided[0].anchor_id, 7);
  EXPECT_EQ(guided[0].blocked_by, front_end.chains(7)[0].why_not()->blocked_by);  // what holds it now
  ASSERT_EQ(guided[0].best.size(), request.best);
  EXPECT_LE(guided[0].best[0].region_m, guided[0].region_m);
  double fewest = std::numeric_limits<double>::infinity();
  for (const CandidateForecast& c : guided[0].best) {
    EXPECT_LE((c.p_world_candidate - front_end.chains(7)[0].p_world_tag().back()).lpNorm<Eigen::Infinity>(), 2.0 + 1e-9);
    fewest = std::min(fewest, c.samples_to_certify);
  }
  EXPECT_DOUBLE_EQ(guided[0].seconds_to_certify, fewest / 20.0);
}

}  // namespace
}  // namespace anchorbench::estimator
