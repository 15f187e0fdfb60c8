#include "anchorbench/estimator/anchor_initializer.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "anchorbench/estimator/height_check.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

using testing::PassBy;

// Named, not `{}`: GCC 12 warns falsely (-Wmaybe-uninitialized) on brace temporaries of it.
const PaperChainOptions kDefaults;

// The consistency check, the given trigger and LS + adaptive NLS, typed, without a registry.
AnchorInitializer Chain(std::unique_ptr<InitTrigger> trigger, const InitializerOptions& options = {}) {
  return AnchorInitializer(7, options, std::make_unique<ConsistencyFilter>(), std::move(trigger),
                           std::make_shared<AnchorSolver>());
}

TEST(AnchorInitializer, GatedFiresOnceWhenPdopDropsBelowThreshold) {
  const Eigen::Vector3d p_anchor(0, 4, 3);
  AnchorInitializer initializer = MakePaperInitializer(7, kDefaults);
  std::optional<InitEvent> event;
  double pdop_before = 0.0;
  for (const RangeSample& s : PassBy(p_anchor, 0.05, 1)) {
    const FeedResult fed = initializer.Feed(s);
    if (fed.event) {
      ASSERT_FALSE(event.has_value()) << "fired twice";
      event = fed.event;
      EXPECT_LT(fed.pdop, 1.0);
      EXPECT_GE(pdop_before, 1.0);  // the trigger fires on the first sample below the threshold
    }
    if (!event) pdop_before = fed.pdop;
  }
  ASSERT_TRUE(event.has_value());
  EXPECT_EQ(event->anchor_id, 7);
  EXPECT_EQ(event->n_used, static_cast<int>(initializer.range_m().size()));
  // Error budget: sigma * PDOP = 0.05 m; allow 5x for the bias column and a single realization.
  EXPECT_LT((event->solve.p_world_anchor - p_anchor).norm(), 0.25);
  EXPECT_FALSE(initializer.Finish(event->t_s).has_value());
}

TEST(AnchorInitializer, FixedWindowSolvesOnAllDataAtFinish) {
  const Eigen::Vector3d p_anchor(0, 4, 3);
  AnchorInitializer initializer = Chain(std::make_unique<FixedWindowTrigger>());
  const auto samples = PassBy(p_anchor, 0.05, 2);
  for (const RangeSample& s : samples) EXPECT_FALSE(initializer.Feed(s).event.has_value());
  const auto event = initializer.Finish(samples.back().t_s);
  ASSERT_TRUE(event.has_value());
  EXPECT_EQ(event->n_used, static_cast<int>(initializer.range_m().size()));
  EXPECT_GT(event->n_used, static_cast<int>(0.98 * samples.size()));  // tau = 2.8 sigma of a difference
  EXPECT_LT((event->solve.p_world_anchor - p_anchor).norm(), 0.1);
}

// The fixed window's time is its own last sample's: the data's end (other anchors, other tags, a
// range dropped late) does not move it.
TEST(AnchorInitializer, FixedWindowTimeIsItsOwnLastSample) {
  const Eigen::Vector3d p_anchor(0, 4, 3);
  const auto samples = PassBy(p_anchor, 0.05, 2);
  for (const double t_end_s : {samples.back().t_s, samples.back().t_s + 100.0}) {
    AnchorInitializer initializer = Chain(std::make_unique<FixedWindowTrigger>());
    double t_last_accepted_s = -1.0;
    for (const RangeSample& s : samples) {
      if (initializer.Feed(s).accepted) t_last_accepted_s = s.t_s;
    }
    const auto event = initializer.Finish(t_end_s);
    ASSERT_TRUE(event.has_value());
    EXPECT_EQ(event->t_s, t_last_accepted_s) << "data ending at " << t_end_s;
  }
}

TEST(AnchorInitializer, NeverFiresOnAStraightLine) {
  AnchorInitializer initializer = MakePaperInitializer(1, kDefaults);
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector3d p(0.05 * k, 0.0, 1.0);
    const FeedResult fed = initializer.Feed({0.1 * k, 0, 1, (p - Eigen::Vector3d(50, 3, 3)).norm(), p});
    EXPECT_FALSE(fed.event.has_value());
    EXPECT_FALSE(std::isnan(fed.pdop));
  }
}

TEST(AnchorInitializer, RejectsNonPositiveRanges) {
  AnchorInitializer initializer = MakePaperInitializer(1, kDefaults);
  EXPECT_FALSE(initializer.Feed({0.0, 0, 1, 0.0, Eigen::Vector3d::Zero()}).accepted);
  EXPECT_FALSE(initializer.Feed({0.1, 0, 1, -1.0, Eigen::Vector3d::Zero()}).accepted);
  EXPECT_TRUE(initializer.Feed({0.2, 0, 1, 3.0, Eigen::Vector3d::Zero()}).accepted);
}

// Deferred solves give exactly the inline results, including retries after failed solves: the
// pass-by starts on a straight stretch where the first solves are degenerate.
TEST(AnchorInitializer, DeferredSolvesGiveTheInlineResults) {
  const auto samples = PassBy(Eigen::Vector3d(0, 4, 3), 0.05, 3);
  for (int every : {1, 7, 1000}) {  // run the pending solve after every sample, every 7th, or at the end
    AnchorInitializer inline_solves = Chain(std::make_unique<SampleCountTrigger>(25));
    AnchorInitializer deferred = Chain(std::make_unique<SampleCountTrigger>(25));
    deferred.SetDeferSolves(true);
    std::optional<InitEvent> a, b;
    int pending_seen = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (const FeedResult fed = inline_solves.Feed(samples[i]); fed.event) a = fed.event;
      pending_seen += deferred.Feed(samples[i]).solve_pending;
      if (i % every == 0) {
        while (deferred.solve_pending()) {
          if (auto event = deferred.RunPendingSolve()) b = event;
        }
      }
    }
    if (auto event = deferred.Finish(samples.back().t_s)) b = event;
    ASSERT_TRUE(a && b) << every;
    EXPECT_GT(pending_seen, 0);
    EXPECT_EQ(a->t_s, b->t_s);
    EXPECT_EQ(a->n_used, b->n_used);
    EXPECT_EQ(a->pdop_closest_point, b->pdop_closest_point);
    EXPECT_EQ(a->solve.p_world_anchor, b->solve.p_world_anchor);
    EXPECT_EQ(inline_solves.last_failed_solve().has_value(), deferred.last_failed_solve().has_value());
  }
}

// With the cap reached, `thin` keeps every 2^k-th sample over the whole run, `keep_first` the
// first ones; either way the buffer never exceeds the cap and the PDOP still counts everything.
TEST(AnchorInitializer, TheBufferStaysWithinItsCap) {
  const auto samples = PassBy(Eigen::Vector3d(0, 4, 3), 0.05, 4);
  for (BufferPolicy policy : {BufferPolicy::kThin, BufferPolicy::kKeepFirst}) {
    InitializerOptions options;
    options.max_buffered_samples = 100;
    options.at_cap = policy;
    options.height_check.enabled = false;  // the pass is flat: this test is about the buffer
    AnchorInitializer initializer(7, options, std::make_unique<NullFilter>(), std::make_unique<FixedWindowTrigger>(),
                                  std::make_shared<AnchorSolver>());
    const double* const buffer = initializer.range_m().data();  // reserved when made: never moved
    for (const RangeSample& s : samples) {
      initializer.Feed(s);
      ASSERT_LE(initializer.range_m().size(), 100u);
      ASSERT_EQ(initializer.range_m().data(), buffer);
    }
    EXPECT_EQ(initializer.pdop().count(), static_cast<int>(samples.size()));
    EXPECT_EQ(initializer.samples_not_buffered() + static_cast<long>(initializer.range_m().size()),
              static_cast<long>(samples.size()));
    if (policy == BufferPolicy::kKeepFirst) {
      EXPECT_EQ(initializer.range_m().back(), samples[99].range_m);
    } else {
      // 1200 samples into 100 slots: every 16th is kept (1200 / 16 = 75), the last kept is 1184.
      EXPECT_EQ(initializer.range_m().size(), 75u);
      EXPECT_EQ(initializer.range_m()[1], samples[16].range_m);
      EXPECT_EQ(initializer.range_m().back(), samples[1184].range_m);
    }
    const auto event = initializer.Finish(samples.back().t_s);
    ASSERT_TRUE(event);
    EXPECT_TRUE(Succeeded(event->solve.status));
  }
}

// A solve whose budget runs out is a failed solve: the anchor is not initialized on it, the
// failure is kept, and the initializer waits for more data before it tries again.
TEST(AnchorInitializer, ASpentSolveBudgetIsAFailedSolve) {
  AnchorSolverOptions solver;
  solver.nls.max_passes = 1;
  AnchorInitializer initializer(7, InitializerOptions{}, std::make_unique<ConsistencyFilter>(),
                                std::make_unique<SampleCountTrigger>(25), std::make_shared<AnchorSolver>(solver));
  for (const RangeSample& s : PassBy(Eigen::Vector3d(0, 4, 3), 0.05, 8)) EXPECT_FALSE(initializer.Feed(s).event);
  EXPECT_FALSE(initializer.initialized());
  ASSERT_TRUE(initializer.last_failed_solve().has_value());
  EXPECT_EQ(initializer.last_failed_solve()->solve.status, SolveStatus::kBudgetSpent);
}

// A tag weaving at 10 Hz within 3 mm of one height, ranging anchor 7 (testing::WeavingData): the
// mirror through its plane fits as well.
std::vector<RangeSample> FlatWeave() {
  const testing::AnchorData flat = testing::WeavingData(Eigen::Vector3d(3.0, 4.0, 4.5), 0.2, 0.003, 0.05, 1);
  std::vector<RangeSample> samples;
  for (std::size_t k = 0; k < flat.range_m.size(); ++k) {
    samples.push_back({0.1 * static_cast<double>(k), 0, 7, flat.range_m[k], flat.p_world_tag[k]});
  }
  return samples;
}

// A solve the mirror check refused says so in why_not(), with the check's numbers: the fixed
// window's at the end, and an online trigger's while it waits to retry.
TEST(AnchorInitializer, AMirrorRefusalIsWhyNotWithTheChecksNumbers) {
  const std::vector<RangeSample> samples = FlatWeave();
  for (const bool online : {false, true}) {
    std::unique_ptr<InitTrigger> trigger = online ? std::unique_ptr<InitTrigger>(std::make_unique<SampleCountTrigger>(300))
                                                  : std::make_unique<FixedWindowTrigger>();
    AnchorInitializer initializer(7, InitializerOptions{}, std::make_unique<NullFilter>(), std::move(trigger),
                                  std::make_shared<AnchorSolver>());
    for (const RangeSample& s : samples) EXPECT_FALSE(initializer.Feed(s).event);
    initializer.Finish(samples.back().t_s);
    ASSERT_FALSE(initializer.initialized());
    ASSERT_TRUE(initializer.last_failed_solve().has_value());
    const SolveResult& refused = initializer.last_failed_solve()->solve;
    EXPECT_EQ(refused.status, SolveStatus::kHeightUnobservable);
    ASSERT_TRUE(refused.mirror_refusal.has_value());
    const std::optional<Judgement> why = initializer.why_not();
    ASSERT_TRUE(why.has_value());
    EXPECT_EQ(why->blocked_by, "mirror") << (online ? "online" : "fixed window");
    EXPECT_EQ(why->value, refused.mirror_refusal->evidence);
    EXPECT_EQ(why->limit, HeightCheckOptions{}.min_evidence);
    EXPECT_EQ(why->samples_needed, refused.mirror_refusal->SamplesNeeded());
    EXPECT_GT(why->samples_needed, 10.0 * static_cast<double>(samples.size()));  // 3 mm of height: not soon
  }
}

// The triggers that solve for their own estimate say why they wait too: their DOP at the estimate
// against the threshold, or, where the mirror check refused their solve, the mirror's numbers.
TEST(AnchorInitializer, SolvingTriggersSayWhyTheyWait) {
  const auto checked = std::make_shared<HeightCheckedSolver>(std::make_shared<AnchorSolver>(), HeightCheckOptions{});
  const std::vector<RangeSample> weave = FlatWeave();
  const std::vector<RangeSample> pass = PassBy(Eigen::Vector3d(0, 4, 3), 0.05, 1);
  for (const bool region : {false, true}) {
    const auto make = [&] {
      return region ? std::unique_ptr<InitTrigger>(std::make_unique<ConfidenceRegionDopTrigger>(checked, 1e-3, SolveCadence(10, 1.1), 1.0))
                    : std::make_unique<EstimatePdopTrigger>(checked, 1e-3, SolveCadence(10, 1.1));
    };
    const std::string_view test = region ? "dop4" : "pdop";
    AnchorInitializer on_flat(7, InitializerOptions{}, std::make_unique<NullFilter>(), make(), checked);
    for (const RangeSample& s : weave) on_flat.Feed(s);
    ASSERT_TRUE(on_flat.why_not().has_value());
    EXPECT_EQ(on_flat.why_not()->blocked_by, "mirror") << test;
    EXPECT_GT(on_flat.why_not()->samples_needed, 10.0 * static_cast<double>(weave.size())) << test;
    AnchorInitializer on_pass(7, InitializerOptions{}, std::make_unique<NullFilter>(), make(), checked);
    for (const RangeSample& s : pass) on_pass.Feed(s);  // a threshold no geometry meets
    ASSERT_TRUE(on_pass.why_not().has_value());
    EXPECT_EQ(on_pass.why_not()->blocked_by, test);
    EXPECT_GT(on_pass.why_not()->value, 1e-3);
    EXPECT_EQ(on_pass.why_not()->limit, 1e-3);
  }
}

TEST(InitializerOptions, ValidationNamesTheProblem) {
  InitializerOptions options;
  std::string why;
  EXPECT_TRUE(options.IsValid(&why));
  options.min_samples = 5;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_EQ(why.rfind("min_samples", 0), 0u) << why;
  options = {};
  options.retry_growth = 1e300;  // would overflow the retry size
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_EQ(why.rfind("retry_growth", 0), 0u) << why;
  options = {};
  options.max_buffered_samples = 30;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_EQ(why.rfind("max_buffered_samples", 0), 0u) << why;
}

}  // namespace
}  // namespace anchorbench::estimator
