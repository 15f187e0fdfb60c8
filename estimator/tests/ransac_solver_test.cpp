// RANSAC in both schemes: the minimal subsets with the adaptive count (ours, the default) and the
// Table II baseline (every subset solved in full, a fixed count).
#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

const Eigen::Vector3d kRansacAnchor(0, 4, 3);

struct PassData {
  std::vector<Eigen::Vector3d> p;
  std::vector<double> d;
};

// The weaving pass (sigma 0.05 m), with every `every`-th range 2-6 m long (NLOS).
PassData WithOutliers(int every, std::uint64_t seed) {
  PassData out;
  auto rng = testing::TestStream(seed + 100);
  int k = 0;
  for (const RangeSample& s : testing::PassBy(kRansacAnchor, 0.05, seed)) {
    out.p.push_back(s.p_world_tag);
    out.d.push_back(s.range_m + (every > 0 && k++ % every == 0 ? rng.Uniform(2.0, 6.0) : 0.0));
  }
  return out;
}

std::shared_ptr<const Solver> PlainLeastSquares() {
  AnchorSolverOptions options;
  options.nls.kernel = KernelMode::kL2;
  return std::make_shared<AnchorSolver>(options);
}

RansacOptions TableII() {
  RansacOptions options;
  options.scheme = RansacScheme::kFullSolve;
  options.success_probability = 0.95;
  options.subset_size = 60;
  return options;
}

double Error(const SolveResult& result) { return (result.p_world_anchor - kRansacAnchor).norm(); }

// A third of the ranges NLOS: plain least squares lands off (the bias soaks up part); the minimal
// scheme finds the anchor at its floor of draws. The Table II baseline cannot: a subset of 60
// is clean with probability (2/3)^60 = 3e-11, and its count assumes 10% outliers.
TEST(Ransac, MinimalSchemeFindsTheAnchorThroughAThirdOfOutliers) {
  const PassData data = WithOutliers(3, 1);
  const auto inner = PlainLeastSquares();
  const SolveResult minimal = RansacSolver(inner, RansacOptions{}, 5).Solve(data.p, data.d);
  ASSERT_TRUE(Succeeded(minimal.status));
  EXPECT_LT(Error(minimal), 0.05);
  EXPECT_GT(Error(inner->Solve(data.p, data.d)), 4.0 * Error(minimal));
  // w = 2/3 asks for log(0.01) / log(1 - (2/3)^6) = 51 draws: the floor's, plus the solve's iterations.
  EXPECT_LT(minimal.iterations, RansacOptions{}.min_subsets + 50);
  const SolveResult full = RansacSolver(inner, TableII(), 5).Solve(data.p, data.d);
  EXPECT_GT(Error(full), 1.0);
  EXPECT_GT(full.iterations, 1666);
}

// At the 10% of outliers the baseline assumes, both find it.
TEST(Ransac, BothSchemesFindTheAnchorAtTenPercent) {
  const PassData data = WithOutliers(10, 1);
  const auto inner = PlainLeastSquares();
  EXPECT_LT(Error(RansacSolver(inner, RansacOptions{}, 5).Solve(data.p, data.d)), 0.05);
  EXPECT_LT(Error(RansacSolver(inner, TableII(), 5).Solve(data.p, data.d)), 0.05);
}

// The count follows the data: clean ranges stop the draws at the floor; with half of them outliers
// at least log(0.01) / log(1 - 0.5^6) = 293 (the share a hypothesis of 6 noisy ranges sees is at
// most the true one), and not the cap.
TEST(Ransac, DrawsFollowTheObservedInlierShare) {
  const auto inner = std::make_shared<DoubleDifferenceLsSolver>();  // one iteration: iterations - 1 = draws
  const RansacSolver ransac(inner, RansacOptions{}, 3);
  const PassData clean = WithOutliers(0, 2), half = WithOutliers(2, 2);
  EXPECT_EQ(ransac.Solve(clean.p, clean.d).iterations - 1, RansacOptions{}.min_subsets);
  const int draws = ransac.Solve(half.p, half.d).iterations - 1;
  EXPECT_GE(draws, 293);
  EXPECT_LT(draws, RansacOptions{}.max_subsets);
}

// Same seed, same subsets, same bytes; another seed draws other subsets.
TEST(Ransac, RepeatsExactlyForOneSeed) {
  const PassData data = WithOutliers(4, 3);
  const auto inner = PlainLeastSquares();
  const SolveResult a = RansacSolver(inner, RansacOptions{}, 9).Solve(data.p, data.d);
  const SolveResult b = RansacSolver(inner, RansacOptions{}, 9).Solve(data.p, data.d);
  EXPECT_EQ(a.p_world_anchor, b.p_world_anchor);
  EXPECT_EQ(a.bias_m, b.bias_m);
  EXPECT_EQ(a.iterations, b.iterations);
}

// Too few samples to leave any out: the inner solver alone; all outliers of one kind leave no
// consensus big enough to solve.
TEST(Ransac, SmallOrHopelessInputsSayWhatHappened) {
  const PassData data = WithOutliers(0, 4);
  const auto inner = PlainLeastSquares();
  const std::span<const Eigen::Vector3d> few_p(data.p.data(), 6);
  const std::span<const double> few_d(data.d.data(), 6);
  EXPECT_EQ(RansacSolver(inner, RansacOptions{}, 1).Solve(few_p, few_d).p_world_anchor,
            inner->Solve(few_p, few_d).p_world_anchor);
  RansacOptions tight;
  tight.inlier_threshold_m = 1e-9;  // no sample is within a nanometre of any hypothesis
  const SolveResult none = RansacSolver(inner, tight, 1).Solve(data.p, data.d);
  EXPECT_FALSE(Succeeded(none.status));
}

}  // namespace
}  // namespace anchorbench::estimator
