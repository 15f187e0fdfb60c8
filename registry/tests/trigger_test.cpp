// Every built-in trigger against a direct computation of its rule on the same samples.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "anchorbench/testing/paper_estimator.hpp"

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/pdop.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/testing/test_data.hpp"
#include "builtins.hpp"

namespace anchorbench::registry {
namespace {

using testing::Builtins;
using estimator::AnchorInitializer;
using estimator::FeedResult;
using estimator::InitEvent;
using estimator::RangeSample;
using estimator::SolveResult;
using anchorbench::testing::PassBy;

// Named, not `{}`: GCC 12 warns falsely (-Wmaybe-uninitialized) on brace temporaries of it.
const schema::EstimatorConfig kDefaults = anchorbench::testing::PaperEstimator();

const Eigen::Vector3d kAnchor(0, 4, 3);

// Feeds the samples; returns the sample index of the event (-1 if none) and the initializer.
struct Fed {
  int index = -1;
  std::optional<InitEvent> event;
};
Fed FeedAll(AnchorInitializer& initializer, const std::vector<RangeSample>& samples) {
  Fed fed;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    FeedResult r = initializer.Feed(samples[i]);
    if (r.event) {
      EXPECT_EQ(fed.index, -1) << "fired twice";
      fed.index = static_cast<int>(i);
      fed.event = r.event;
    }
  }
  return fed;
}

// With no filter every sample is accepted, so sample i is the (i+1)-th accepted one.
schema::EstimatorConfig Unfiltered() {
  schema::EstimatorConfig options = anchorbench::testing::PaperEstimator();
  options.filter.kind = "none";
  return options;
}

TEST(Triggers, SampleCountFiresAtTheCount) {
  schema::EstimatorConfig options = Unfiltered();
  options.trigger.sample_count = 137;
  AnchorInitializer initializer = MakeInitializer(Builtins(), 7, options, "sample_count", 0);
  const Fed fed = FeedAll(initializer, PassBy(kAnchor, 0.05, 1));
  EXPECT_EQ(fed.index, 136);
  ASSERT_TRUE(fed.event);
  EXPECT_EQ(fed.event->n_used, 137);
}

TEST(Triggers, SampleCountBelowMinSamplesActsAsMinSamples) {
  schema::EstimatorConfig options = Unfiltered();
  options.trigger.sample_count = 5;  // min_samples = 20 still applies
  AnchorInitializer below = MakeInitializer(Builtins(), 7, options, "sample_count", 0);
  options.trigger.sample_count = options.initializer.min_samples;
  AnchorInitializer at = MakeInitializer(Builtins(), 7, options, "sample_count", 0);
  const auto samples = PassBy(kAnchor, 0.05, 1);
  const Fed a = FeedAll(below, samples), b = FeedAll(at, samples);
  ASSERT_TRUE(a.event && b.event);
  EXPECT_EQ(a.index, b.index);  // both retry after the first 20 samples fail to solve, alike
  EXPECT_GE(a.event->n_used, 20);
}

TEST(Triggers, TimeoutFiresOnTheFirstSampleThatLongAfterTheFirst) {
  schema::EstimatorConfig options = Unfiltered();
  options.trigger.timeout_s = 12.25;
  AnchorInitializer initializer = MakeInitializer(Builtins(), 7, options, "timeout", 0);
  const auto samples = PassBy(kAnchor, 0.05, 1);  // 10 Hz from t = 0
  const Fed fed = FeedAll(initializer, samples);
  ASSERT_TRUE(fed.event);
  EXPECT_EQ(fed.index, 123);  // t = 12.3 s is the first >= 12.25 s
  EXPECT_DOUBLE_EQ(fed.event->t_s, samples[123].t_s);
}

TEST(Triggers, FixedWindowNeverFiresOnlineAndSolvesEverythingAtFinish) {
  AnchorInitializer initializer = MakeInitializer(Builtins(), 7, Unfiltered(), "fixed_window", 0);
  const auto samples = PassBy(kAnchor, 0.05, 1);
  EXPECT_EQ(FeedAll(initializer, samples).index, -1);
  const auto event = initializer.Finish(samples.back().t_s);
  ASSERT_TRUE(event);
  EXPECT_EQ(event->n_used, static_cast<int>(samples.size()));
  EXPECT_TRUE(initializer.initialized());
}

// pdop_ls re-solves every evaluate_every samples from the first eligible one; it fires at the
// first evaluation whose LS estimate gives Eq. (2)-(3) below the threshold.
TEST(Triggers, LsEvaluatesOnItsCadenceAndFiresOnTheFirstGoodEstimate) {
  const auto samples = PassBy(kAnchor, 0.05, 3);
  for (int every : {1, 10}) {
    schema::EstimatorConfig options = Unfiltered();
    options.trigger.evaluate_every = every;
    AnchorInitializer initializer = MakeInitializer(Builtins(), 7, options, "pdop_ls", 0);
    const Fed fed = FeedAll(initializer, samples);
    int expected = -1;
    std::vector<Eigen::Vector3d> p;
    std::vector<double> d;
    for (std::size_t i = 0; i < samples.size() && expected < 0; ++i) {
      p.push_back(samples[i].p_world_tag);
      d.push_back(samples[i].range_m);
      if (p.size() < 20 || (p.size() - 20) % static_cast<std::size_t>(every) != 0) continue;
      const SolveResult ls = estimator::SolveDoubleDifferenceLs(p, d);
      if (estimator::Succeeded(ls.status) && estimator::GeometryPdop(p, d, ls.p_world_anchor) < 1.0) expected = static_cast<int>(i);
    }
    ASSERT_GE(expected, 0) << "every " << every;
    EXPECT_EQ(fed.index, expected) << "every " << every;
  }
}

// The solving triggers' cadence: the first eligible sample, then the first count at least `every`
// past the last and `growth` times it; growth 1 is the fixed cadence.
TEST(Triggers, SolveCadenceGrowsGeometrically) {
  auto evaluations = [](int every, double growth) {
    estimator::SolveCadence cadence(every, growth);
    std::vector<std::size_t> at;
    estimator::TriggerInput in;
    for (std::size_t n = 1; n <= 5000; ++n) {
      in.n_admitted = n;
      in.eligible = n >= 20;
      if (cadence.Due(in)) at.push_back(n);
    }
    return at;
  };
  const std::vector<std::size_t> fixed = evaluations(10, 1.0);
  ASSERT_EQ(fixed.size(), 499u);
  EXPECT_EQ(fixed[1], 30u);
  const std::vector<std::size_t> grown = evaluations(10, 1.5);
  EXPECT_EQ((std::vector<std::size_t>(grown.begin(), grown.begin() + 6)), (std::vector<std::size_t>{20, 30, 45, 68, 102, 153}));
  std::size_t solved = 0;
  for (std::size_t n : grown) solved += n;
  EXPECT_LT(solved, 3u * 5000u);  // the solves' total stays O(N): sum n_i <= N g / (g - 1)
}

TEST(Triggers, NlsUsesTheAnchorsSolver) {
  const auto samples = PassBy(kAnchor, 0.05, 4);
  schema::EstimatorConfig options = Unfiltered();
  options.solver = "lm_l2";
  AnchorInitializer initializer = MakeInitializer(Builtins(), 7, options, "pdop_nls", 0);
  const Fed fed = FeedAll(initializer, samples);
  ASSERT_TRUE(fed.event);
  const auto n = static_cast<std::size_t>(fed.event->n_used);
  const std::span<const Eigen::Vector3d> p(initializer.p_world_tag().data(), n);
  const std::span<const double> d(initializer.range_m().data(), n);
  // The event's solve is the trigger's estimate (same solver, same data): its PDOP is below 1.
  EXPECT_LT(estimator::GeometryPdop(p, d, fed.event->solve.p_world_anchor), 1.0);
  EXPECT_EQ((n - 20) % 10, 0u);
  EXPECT_LT((fed.event->solve.p_world_anchor - kAnchor).norm(), 0.5);
}

// The index of the first sample, from the 20th on, whose closest-point value (a ClosestPointPdop
// member) is below the threshold: where a closest-point trigger must fire.
int FirstBelow(const std::vector<RangeSample>& samples, double (estimator::ClosestPointPdop::*value)() const,
               double threshold) {
  estimator::ClosestPointPdop direct;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    direct.Add(samples[i].p_world_tag, samples[i].range_m);
    if (i + 1 >= 20 && (direct.*value)() < threshold) return static_cast<int>(i);
  }
  return -1;
}

// The sample indices at which the paper's trigger and `trigger` fire on the same pass (-1: never),
// and where `trigger` should fire by its closest-point value.
struct Fired {
  int paper, own, expected;
};
Fired BesideThePapers(const schema::EstimatorConfig& options, const std::string& trigger,
                      double (estimator::ClosestPointPdop::*value)() const, double threshold) {
  const auto samples = PassBy(kAnchor, 0.05, 6);
  AnchorInitializer paper = MakeInitializer(Builtins(), 7, options, "pdop_closest_point", 0);
  AnchorInitializer own = MakeInitializer(Builtins(), 7, options, trigger, 0);
  return {FeedAll(paper, samples).index, FeedAll(own, samples).index, FirstBelow(samples, value, threshold)};
}

// dop4_closest_point: the closest-point rows with a bias column, fired on the first sample whose
// 4-column DOP is below its threshold; never before the paper's 3-column one.
TEST(Triggers, ClosestPointBiasAwareFiresOnItsOwnThresholdAndNeverBeforeThePapers) {
  schema::EstimatorConfig options = Unfiltered();
  options.trigger.bias_aware_threshold = 1.0;
  const Fired f = BesideThePapers(options, "dop4_closest_point", &estimator::ClosestPointPdop::BiasAwareValue, 1.0);
  ASSERT_TRUE(f.paper >= 0 && f.own >= 0);
  EXPECT_GT(f.own, f.paper);
  EXPECT_EQ(f.own, f.expected);
}

// hdop_closest_point: the x-y block of the closest-point rows, fired on the first sample whose
// horizontal DOP is below its threshold; never after the paper's (the block's DOP is smaller).
TEST(Triggers, ClosestPointHorizontalFiresOnItsOwnThresholdAndNeverAfterThePapers) {
  schema::EstimatorConfig options = Unfiltered();
  options.trigger.horizontal_threshold = 1.0;
  const Fired f = BesideThePapers(options, "hdop_closest_point", &estimator::ClosestPointPdop::HorizontalValue, 1.0);
  ASSERT_TRUE(f.paper >= 0 && f.own >= 0);
  EXPECT_LE(f.own, f.paper);
  EXPECT_EQ(f.own, f.expected);
}

// The height prior of each anchor: a fixed height for all, or the reference's shifted by the
// offset; a reference prior without a reference is refused; solvers without a prior term refuse it.
TEST(HeightPriorConfig, EachAnchorGetsItsPriorAndSolversWithoutOneRefuseIt) {
  schema::HeightPriorConfig config;
  EXPECT_FALSE(config.For(3, std::nullopt));
  config.enabled = true;
  config.z_m = 2.5;
  config.offset_m = 0.5;
  EXPECT_DOUBLE_EQ(config.For(3, std::nullopt)->z_world_m, 3.0);
  config.from_reference = true;
  EXPECT_DOUBLE_EQ(config.For(3, Eigen::Vector3d(1, 2, 4))->z_world_m, 4.5);
  EXPECT_THROW(config.For(3, std::nullopt), std::invalid_argument);

  schema::EstimatorConfig options = Unfiltered();
  options.height_prior = config;
  for (const char* solver : {"ls_single", "nlopt:LN_BOBYQA"}) {
    options.solver = solver;
    try {
      MakeInitializer(Builtins(), 3, options, "pdop_closest_point", 0, Eigen::Vector3d(1, 2, 4));
      ADD_FAILURE() << solver << " accepted a height prior";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("height prior"), std::string::npos) << e.what();
    }
  }
  options.solver = "lm_adaptive";
  EXPECT_NO_THROW(MakeInitializer(Builtins(), 3, options, "pdop_ls", 0, Eigen::Vector3d(1, 2, 4)));
}

// dop4_confidence solves on its cadence and fires when the worst bias-aware DOP over the
// estimate's 3-sigma region is below its threshold; the worst case is never below the estimate's.
TEST(Triggers, ConfidenceRegionJudgesTheWorstCornerOfTheEstimate) {
  const auto samples = PassBy(kAnchor, 0.05, 7);
  schema::EstimatorConfig options = Unfiltered();
  options.solver = "lm_l2";
  options.trigger.confidence_threshold = 1.5;
  AnchorInitializer initializer = MakeInitializer(Builtins(), 7, options, "dop4_confidence", 0);
  const Fed fed = FeedAll(initializer, samples);
  ASSERT_TRUE(fed.event);
  const auto n = static_cast<std::size_t>(fed.event->n_used);
  EXPECT_EQ((n - 20) % 10, 0u);
  const std::span<const Eigen::Vector3d> p(initializer.p_world_tag().data(), n);
  const double worst = estimator::WorstBiasAwareDop(p, fed.event->solve, 3.0);
  EXPECT_LT(worst, 1.5);
  EXPECT_GE(worst, estimator::BiasAwareDopAt(p, fed.event->solve.p_world_anchor));
  EXPECT_EQ(estimator::WorstBiasAwareDop(p, fed.event->solve, 0.0),
            estimator::BiasAwareDopAt(p, fed.event->solve.p_world_anchor));
}

TEST(Triggers, DefaultChainIsTheRegistrysPaperChain) {
  const auto samples = PassBy(kAnchor, 0.05, 5);
  AnchorInitializer by_hand = estimator::MakePaperInitializer(7);
  AnchorInitializer by_name = MakeInitializer(Builtins(), 7, kDefaults, "pdop_closest_point", 0);
  const Fed a = FeedAll(by_hand, samples), b = FeedAll(by_name, samples);
  ASSERT_TRUE(a.event && b.event);
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.event->solve.p_world_anchor, b.event->solve.p_world_anchor);
}

TEST(Triggers, UnknownNamesAreRefusedWithTheReason) {
  for (const char* name : {"pdop_best", ""}) {
    try {
      MakeInitializer(Builtins(), 7, kDefaults, name, 0);
      FAIL() << "no exception for '" << name << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("unknown trigger"), std::string::npos) << e.what();
    }
  }
  schema::EstimatorConfig bad_filter = kDefaults;
  bad_filter.filter.kind = "median";
  EXPECT_THROW(MakeInitializer(Builtins(), 7, bad_filter, "fixed_window", 0), std::invalid_argument);
  schema::EstimatorConfig bad_solver = kDefaults;
  bad_solver.solver = "nlopt:LN_NOPE";
  EXPECT_THROW(MakeInitializer(Builtins(), 7, bad_solver, "fixed_window", 0), std::invalid_argument);
}

TEST(Triggers, RegistryListsEveryBuiltInWithADescription) {
  const auto entries = Builtins().triggers.List();
  std::vector<std::string> names;
  for (const auto& [name, description] : entries) {
    names.push_back(name);
    EXPECT_FALSE(description.empty()) << name;
  }
  // The built-ins need no truth; the oracles pdop_true and dop4_true are eval's, registered on top by who wants it.
  EXPECT_EQ(names, (std::vector<std::string>{"certified", "dop4_closest_point", "dop4_confidence", "fixed_window", "hdop_closest_point", "pdop_closest_point",
                                             "pdop_ls", "pdop_nls", "sample_count", "timeout"}));
}

}  // namespace
}  // namespace anchorbench::registry
