// The live-core contract of anchor_initializer.hpp, one test per promise: with deferred solves
// Feed() never solves (for every trigger that solves), a pending solve can run on a worker thread
// while Feed() goes on, and distinct initializers run on their own threads; each with the inline
// results.
#include <atomic>
#include <thread>

#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

// The anchor's solver, counting its solves (from any thread).
class CountingSolver : public Solver {
 public:
  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override {
    ++solves;
    return solver_.Solve(p_world_tag, range_m);
  }
  mutable std::atomic<int> solves{0};

 private:
  AnchorSolver solver_;
};

enum class Kind { kPdopLs, kConfidence, kCertified };

// The chain with one of the triggers that solve, each on the counting solver.
AnchorInitializer Chain(Kind kind, const std::shared_ptr<const CountingSolver>& solver) {
  const SolveCadence cadence(10, 1.1);
  std::unique_ptr<InitTrigger> trigger;
  if (kind == Kind::kPdopLs) trigger = std::make_unique<EstimatePdopTrigger>(solver, 1.0, cadence);
  if (kind == Kind::kConfidence) trigger = std::make_unique<ConfidenceRegionDopTrigger>(solver, 1.5, cadence, 3.0);
  if (kind == Kind::kCertified) {
    trigger = std::make_unique<CertifiedTrigger>(solver, AnchorSolverOptions{}, CertificateOptions{},
                                                 HeightCheckOptions{}, TagBiasOptions{},
                                                 [](double s, double slack) { return ConsistencyFilter().TravelBias(s, slack); }, cadence);
  }
  return AnchorInitializer(7, InitializerOptions{}, std::make_unique<ConsistencyFilter>(), std::move(trigger), solver);
}

void ExpectSameEvent(const std::optional<InitEvent>& a, const std::optional<InitEvent>& b) {
  ASSERT_EQ(a.has_value(), b.has_value());
  if (!a) return;
  EXPECT_EQ(a->t_s, b->t_s);
  EXPECT_EQ(a->n_used, b->n_used);
  EXPECT_EQ(a->solve.p_world_anchor, b->solve.p_world_anchor);
  EXPECT_EQ(a->solve.covariance, b->solve.covariance);
}

std::optional<InitEvent> FeedInline(Kind kind, const std::vector<RangeSample>& samples) {
  AnchorInitializer chain = Chain(kind, std::make_shared<CountingSolver>());
  std::optional<InitEvent> event;
  for (const RangeSample& s : samples) {
    if (FeedResult fed = chain.Feed(s); fed.event) event = fed.event;
  }
  if (auto last = chain.Finish(samples.back().t_s)) event = last;
  return event;
}

TEST(LiveCore, DeferredSolvingTriggersNeverSolveInsideFeed) {
  const auto samples = testing::PassBy(Eigen::Vector3d(0, 4, 3), 0.05, 5);
  for (Kind kind : {Kind::kPdopLs, Kind::kConfidence, Kind::kCertified}) {
    auto solver = std::make_shared<CountingSolver>();
    AnchorInitializer chain = Chain(kind, solver);
    chain.SetDeferSolves(true);
    std::optional<InitEvent> event;
    int inside_feed = 0, pending = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const int before = solver->solves;
      pending += chain.Feed(samples[i]).solve_pending;
      inside_feed += solver->solves - before;
      if (i % 5 == 0) {
        while (chain.solve_pending()) {
          if (auto e = chain.RunPendingSolve()) event = e;
        }
      }
    }
    if (auto last = chain.Finish(samples.back().t_s)) event = last;
    EXPECT_EQ(inside_feed, 0) << static_cast<int>(kind);
    EXPECT_GT(pending, 0);
    EXPECT_GT(solver->solves, 1);  // the evaluations ran, outside Feed()
    if (kind == Kind::kPdopLs) {
      EXPECT_TRUE(event.has_value());
    }
    ExpectSameEvent(event, FeedInline(kind, samples));
  }
}

TEST(LiveCore, APendingSolveRunsOnAWorkerWhileFeedGoesOn) {
  const auto samples = testing::PassBy(Eigen::Vector3d(0, 4, 3), 0.05, 6);
  for (Kind kind : {Kind::kPdopLs, Kind::kCertified}) {
    AnchorInitializer chain = Chain(kind, std::make_shared<CountingSolver>());
    chain.SetDeferSolves(true);
    std::optional<InitEvent> event;
    std::size_t i = 0;
    int handed_over = 0;
    while (i < samples.size()) {
      chain.Feed(samples[i++]);
      if (!chain.solve_pending()) continue;
      PendingWork work;
      std::thread worker([&chain, &work] { work = chain.WorkPendingSolve(); });
      for (int k = 0; k < 20 && i < samples.size(); ++k) chain.Feed(samples[i++]);  // the callback goes on
      worker.join();
      ++handed_over;
      if (auto e = chain.CompletePendingSolve(work)) event = e;
    }
    if (auto last = chain.Finish(samples.back().t_s)) event = last;
    EXPECT_GT(handed_over, 0);
    EXPECT_TRUE(event.has_value());
    ExpectSameEvent(event, FeedInline(kind, samples));
  }
}

TEST(LiveCore, DistinctInitializersRunOnTheirOwnThreadsSharingOneSolver) {
  auto solver = std::make_shared<CountingSolver>();
  std::vector<std::vector<RangeSample>> data;
  for (std::uint64_t seed : {7, 8, 9, 10}) data.push_back(testing::PassBy(Eigen::Vector3d(0, 4, 3), 0.05, seed));
  std::vector<std::optional<InitEvent>> events(data.size());
  std::vector<std::thread> threads;
  for (std::size_t a = 0; a < data.size(); ++a) {
    threads.emplace_back([&, a] {
      AnchorInitializer chain = Chain(Kind::kConfidence, solver);
      for (const RangeSample& s : data[a]) {
        if (FeedResult fed = chain.Feed(s); fed.event) events[a] = fed.event;
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_TRUE(events[0].has_value());
  for (std::size_t a = 0; a < data.size(); ++a) ExpectSameEvent(events[a], FeedInline(Kind::kConfidence, data[a]));
}

}  // namespace
}  // namespace anchorbench::estimator
