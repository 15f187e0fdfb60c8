// The mirror check: on a flat path the reflected anchor fits as well and the solve is refused as
// height_unobservable; with height variation in the path the estimate beats its mirror.
#include "anchorbench/estimator/height_check.hpp"

#include <cmath>
#include <limits>
#include <memory>

#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

const Eigen::Vector3d kCheckedAnchor(3.0, 4.0, 4.5);

// A tag weaving in x-y at 1.5 m with a vertical wobble of `wobble_m`, range bias 0.2 m.
testing::AnchorData Path(double wobble_m, double sigma_m, std::uint64_t seed) {
  return testing::WeavingData(kCheckedAnchor, 0.2, wobble_m, sigma_m, seed);
}

// LS + L2 refinement, wrapped in the check or not.
std::shared_ptr<const Solver> Checked(bool checked) {
  AnchorSolverOptions options;
  options.nls.kernel = KernelMode::kL2;
  options.nls.kernel_scale_m = 0.05;
  auto solver = std::make_shared<AnchorSolver>(options);
  if (!checked) return solver;
  return std::make_shared<HeightCheckedSolver>(solver, HeightCheckOptions{});
}

// Exactly flat, the LS is already degenerate; a 3 mm wobble makes it solvable, and the mirror
// as good: unchecked, this noise draw converges to the mirror, 6 m off, as "converged".
TEST(HeightCheck, ANearlyFlatPathIsHeightUnobservableNotAConfidentHeight) {
  const testing::AnchorData flat = Path(0.003, 0.05, 2);
  const SolveResult unchecked = Checked(false)->Solve(flat.p_world_tag, flat.range_m);
  ASSERT_TRUE(Succeeded(unchecked.status));
  EXPECT_GT((unchecked.p_world_anchor - kCheckedAnchor).norm(), 5.0);
  EXPECT_LT(unchecked.p_world_anchor.z(), 1.5);  // below the path: the mirror
  const SolveResult checked = Checked(true)->Solve(flat.p_world_tag, flat.range_m);
  EXPECT_EQ(checked.status, SolveStatus::kHeightUnobservable);
  for (std::uint64_t seed : {1, 3}) {  // the draws that land on the truth are refused as well
    const testing::AnchorData other = Path(0.003, 0.05, seed);
    EXPECT_EQ(Checked(true)->Solve(other.p_world_tag, other.range_m).status, SolveStatus::kHeightUnobservable);
  }
}

TEST(HeightCheck, APathThatChangesHeightBeatsItsMirror) {
  const testing::AnchorData varied = Path(0.1, 0.05, 2);  // 10 cm of height change already suffice
  const SolveResult result = Checked(true)->Solve(varied.p_world_tag, varied.range_m);
  ASSERT_TRUE(Succeeded(result.status)) << ToString(result.status);
  EXPECT_LT((result.p_world_anchor - kCheckedAnchor).norm(), 0.2);
  EXPECT_GT(MirrorEvidence(varied.p_world_tag, varied.range_m, result, 0.1), 100.0);
}

// With the anchor's side known, an ambiguous estimate on the wrong side becomes its mirror (the
// truth here), one on the right side stands; a wrong prior puts the anchor on the wrong side.
TEST(HeightCheck, ASidePriorResolvesTheMirror) {
  AnchorSolverOptions options;
  options.nls.kernel = KernelMode::kL2;
  options.nls.kernel_scale_m = 0.05;
  auto solver = std::make_shared<AnchorSolver>(options);
  HeightCheckOptions above;
  above.side = HeightCheckOptions::Side::kAbove;
  HeightCheckOptions below = above;
  below.side = HeightCheckOptions::Side::kBelow;
  for (std::uint64_t seed : {1, 2, 3}) {  // seed 2 converges to the mirror unchecked
    const testing::AnchorData flat = Path(0.003, 0.05, seed);
    const SolveResult right = HeightCheckedSolver(solver, above).Solve(flat.p_world_tag, flat.range_m);
    ASSERT_TRUE(Succeeded(right.status)) << "seed " << seed;
    EXPECT_LT((right.p_world_anchor - kCheckedAnchor).norm(), 0.3) << "seed " << seed;
    EXPECT_NEAR(right.bias_m, 0.2, 0.1) << "seed " << seed;
    const SolveResult wrong = HeightCheckedSolver(solver, below).Solve(flat.p_world_tag, flat.range_m);
    ASSERT_TRUE(Succeeded(wrong.status));
    EXPECT_LT(wrong.p_world_anchor.z(), 1.5) << "seed " << seed;  // below the path: the prior's cost
    EXPECT_NEAR(wrong.p_world_anchor.head<2>().x(), kCheckedAnchor.x(), 0.3);  // x-y survive a wrong prior
  }
  HeightCheckOptions::Side side;
  EXPECT_TRUE(ParseSide("below", &side));
  EXPECT_EQ(side, HeightCheckOptions::Side::kBelow);
  EXPECT_FALSE(ParseSide("up", &side));
}

// Every `every`-th sample of a path: the same geometry, sparser.
testing::AnchorData EveryNth(const testing::AnchorData& all, std::size_t every) {
  testing::AnchorData sparse{all.p_world_anchor, all.bias_m, {}, {}};
  for (std::size_t k = 0; k < all.range_m.size(); k += every) {
    sparse.p_world_tag.push_back(all.p_world_tag[k]);
    sparse.range_m.push_back(all.range_m[k]);
  }
  return sparse;
}

// A refusal says why and what more data would settle it: on a sparse log of a path with 5 cm of
// height, the samples at which both tests would pass at the rates they show; the same path sampled
// that densely passes. A path with 3 mm of height needs far more than it has, or never.
TEST(HeightCheck, ARefusalSaysHowManySamplesOfTheSamePathWouldSettleIt) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const testing::AnchorData dense = Path(0.05, 0.05, seed);
    const testing::AnchorData sparse = EveryNth(dense, 5);
    const SolveResult refused = Checked(true)->Solve(sparse.p_world_tag, sparse.range_m);
    ASSERT_EQ(refused.status, SolveStatus::kHeightUnobservable) << "seed " << seed;
    ASSERT_TRUE(refused.mirror_refusal.has_value());
    const FitComparison& why = *refused.mirror_refusal;
    EXPECT_EQ(why.samples, sparse.range_m.size());
    EXPECT_EQ(why.evidence_needed, HeightCheckOptions{}.min_evidence);
    EXPECT_EQ(why.separation_needed, HeightCheckOptions{}.min_separation);
    EXPECT_TRUE(why.evidence < why.evidence_needed || why.separation < why.separation_needed);
    const double needed = why.SamplesNeeded();
    EXPECT_GT(needed, static_cast<double>(sparse.range_m.size())) << "seed " << seed;
    EXPECT_LT(needed, static_cast<double>(dense.range_m.size())) << "seed " << seed;
    const SolveResult settled = Checked(true)->Solve(dense.p_world_tag, dense.range_m);
    EXPECT_TRUE(Succeeded(settled.status)) << "seed " << seed << ": " << ToString(settled.status);
    EXPECT_FALSE(settled.mirror_refusal.has_value());
  }
  for (std::uint64_t seed : {1, 2, 3}) {
    const testing::AnchorData flat = Path(0.003, 0.05, seed);
    const SolveResult refused = Checked(true)->Solve(flat.p_world_tag, flat.range_m);
    ASSERT_TRUE(refused.mirror_refusal.has_value());
    EXPECT_GT(refused.mirror_refusal->SamplesNeeded(), 50.0 * static_cast<double>(flat.range_m.size())) << "seed " << seed;
  }
}

TEST(HeightCheck, SamplesNeededGrowsEachTestAtItsOwnRate) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ((FitComparison{3.0, 9.0, 50.0, 100.0, 40}.SamplesNeeded()), 120.0);  // the evidence's rate binds
  EXPECT_DOUBLE_EQ((FitComparison{30.0, 9.0, 20.0, 100.0, 40}.SamplesNeeded()), 200.0);  // the separation's
  EXPECT_EQ((FitComparison{-1.0, 9.0, 500.0, 100.0, 40}.SamplesNeeded()), inf);  // the mirror fits as well
  EXPECT_EQ((FitComparison{3.0, 9.0, 0.0, 100.0, 40}.SamplesNeeded()), inf);     // a flat path
  EXPECT_DOUBLE_EQ((FitComparison{3.0, 9.0, inf, 0.0, 40}.SamplesNeeded()), 120.0);  // a prior separates
}

TEST(HeightCheck, OnByDefaultAndAnchorOnThePlaneHasNoMirror) {
  EXPECT_TRUE(HeightCheckOptions{}.enabled);  // for real logs; the paper's experiments turn it off
  const testing::AnchorData flat = Path(0.03, 0.05, 3);
  EXPECT_TRUE(Succeeded(Checked(false)->Solve(flat.p_world_tag, flat.range_m).status));
  SolveResult on_plane;
  on_plane.p_world_anchor = Eigen::Vector3d(3.0, 4.0, 1.5);
  EXPECT_TRUE(std::isinf(MirrorEvidence(flat.p_world_tag, flat.range_m, on_plane, 0.1)));
  std::string why;
  HeightCheckOptions bad;
  bad.trim_fraction = 0.7;
  EXPECT_FALSE(bad.IsValid(&why));
  EXPECT_NE(why.find("trim_fraction"), std::string::npos);
}

// Three tags whose links differ by 0.2 m, their offsets corrected for another fit (left in the
// ranges here): judged with offsets that are not its own, the true anchor's lead over a fit 1.5 m
// off is a small part of what it is with each fit's own offsets.
TEST(HeightCheck, EachFitIsJudgedWithTheTagsOffsetsThatSuitIt) {
  const testing::AnchorData weave = Path(0.4, 0.02, 5);
  const double offset_m[] = {0.0, 0.25, -0.2};
  std::vector<int> tag_id(weave.p_world_tag.size());
  std::vector<double> range_m(weave.range_m);
  for (std::size_t k = 0; k < range_m.size(); ++k) {
    tag_id[k] = static_cast<int>(k % 3);
    range_m[k] += offset_m[k % 3];
  }
  const Eigen::Vector3d p_off = kCheckedAnchor + Eigen::Vector3d(1.0, -1.0, 0.5);
  const double own = FitEvidenceOwnOffsets(weave.p_world_tag, range_m, tag_id, kCheckedAnchor, 0.2, p_off, 0.2, 0.1);
  const double shared = FitEvidence(weave.p_world_tag, range_m, kCheckedAnchor, 0.2, p_off, 0.2, 0.1);
  EXPECT_GT(own, 10.0 * shared);  // 3.5e5 against 1.8e3 in this draw
  EXPECT_GT(own, 1000.0);
}

}  // namespace
}  // namespace anchorbench::estimator
