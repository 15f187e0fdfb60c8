// LiveFrontEnd: several threads add while workers solve, to the single-threaded events; an add
// never waits for a solve; a reset and the end of data wait for the solves running.
#include "anchorbench/estimator/live_front_end.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <tuple>

#include <gtest/gtest.h>

#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

// Per anchor: the paper's chain and a sample-count chain (both online), and a fixed window.
std::vector<AnchorInitializer> Chains(int anchor_id) {
  std::vector<AnchorInitializer> chains;
  chains.push_back(MakePaperInitializer(anchor_id));
  chains.emplace_back(anchor_id, InitializerOptions{}, std::make_unique<ConsistencyFilter>(),
                      std::make_unique<SampleCountTrigger>(120), std::make_shared<AnchorSolver>());
  chains.emplace_back(anchor_id, InitializerOptions{}, std::make_unique<ConsistencyFilter>(),
                      std::make_unique<FixedWindowTrigger>(), std::make_shared<AnchorSolver>());
  return chains;
}

// Anchor a's samples: a pass by it at 0.05 m noise, tag a (one thread per anchor feeds them).
std::vector<RangeSample> AnchorSamples(int anchor_id) {
  std::vector<RangeSample> samples =
      testing::PassBy(Eigen::Vector3d(3.0 * anchor_id, 4.0, 2.5), 0.05, static_cast<std::uint64_t>(anchor_id));
  for (RangeSample& s : samples) {
    s.anchor_id = anchor_id;
    s.tag_id = anchor_id;
  }
  return samples;
}

using Key = std::tuple<int, std::size_t, double, int, double, double, double>;
std::vector<Key> Keys(const std::vector<FrontEndEvent>& events) {
  std::vector<Key> keys;
  for (const FrontEndEvent& e : events) {
    const Eigen::Vector3d& p = e.init.solve.p_world_anchor;
    keys.emplace_back(e.anchor_id, e.chain, e.init.t_s, e.init.n_used, p.x(), p.y(), p.z());
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

TEST(LiveFrontEnd, FourAddingThreadsAndTwoWorkersGiveTheSingleThreadedEvents) {
  constexpr int kAnchors = 4;
  FrontEnd single(Chains);
  std::vector<std::vector<RangeSample>> per_anchor;
  double t_end_s = 0.0;
  for (int a = 1; a <= kAnchors; ++a) {
    per_anchor.push_back(AnchorSamples(a));
    for (const RangeSample& s : per_anchor.back()) single.AddSample(s);
    t_end_s = std::max(t_end_s, per_anchor.back().back().t_s);
  }
  single.Finish(t_end_s);
  const std::vector<Key> expected = Keys(single.TakeEvents());
  ASSERT_GE(expected.size(), static_cast<std::size_t>(2 * kAnchors));

  LiveFrontEnd live(Chains, {});
  std::atomic<bool> adding{true};
  std::vector<std::thread> threads;
  for (int w = 0; w < 2; ++w) {
    threads.emplace_back([&] {
      while (adding) {
        if (live.RunPendingSolves(1) == 0) std::this_thread::yield();
      }
    });
  }
  std::vector<std::thread> adders;
  for (const std::vector<RangeSample>& samples : per_anchor) {
    adders.emplace_back([&live, &samples] {
      for (const RangeSample& s : samples) live.AddSample(s);
    });
  }
  for (std::thread& t : adders) t.join();
  adding = false;
  for (std::thread& t : threads) t.join();
  live.Finish(t_end_s);
  EXPECT_EQ(Keys(live.TakeEvents()), expected);
  EXPECT_EQ(live.counters().samples, single.counters().samples);
}

// A solver that blocks until released: a solve in progress while ranges keep coming.
class GateSolver : public Solver {
 public:
  SolveResult Solve(std::span<const Eigen::Vector3d> p, std::span<const double> d) const override {
    entered = true;
    while (!released) std::this_thread::yield();
    return AnchorSolver().Solve(p, d);
  }
  mutable std::atomic<bool> entered{false};
  mutable std::atomic<bool> released{false};
};

TEST(LiveFrontEnd, AddingNeverWaitsForASolveAndRunPendingSolvesHonoursItsLimits) {
  auto gate = std::make_shared<GateSolver>();
  auto counting_chain = [](std::shared_ptr<const Solver> solver) {
    return [solver](int anchor_id) {
      std::vector<AnchorInitializer> chains;
      chains.emplace_back(anchor_id, InitializerOptions{}, std::make_unique<ConsistencyFilter>(),
                          std::make_unique<SampleCountTrigger>(30), solver);
      return chains;
    };
  };
  LiveFrontEnd live(counting_chain(gate), {});
  const std::vector<RangeSample> samples = AnchorSamples(1);
  FrontEnd single(counting_chain(std::make_shared<AnchorSolver>()));
  for (const RangeSample& s : samples) single.AddSample(s);
  for (std::size_t k = 0; k < 40; ++k) live.AddSample(samples[k]);
  ASSERT_EQ(live.pending_solves(), 1u);
  EXPECT_EQ(live.RunPendingSolves(0), 0u);  // a count of 0 runs nothing
  EXPECT_EQ(live.RunPendingSolves(5, LiveFrontEnd::Clock::now()), 0u);  // nor does a deadline passed
  std::thread worker([&] { live.RunPendingSolves(); });
  while (!gate->entered) std::this_thread::yield();
  // The solve is blocked inside the solver: adding goes on and returns.
  for (std::size_t k = 40; k < samples.size(); ++k) live.AddSample(samples[k]);
  EXPECT_TRUE(live.TakeEvents().empty());
  gate->released = true;
  worker.join();
  live.RunPendingSolves();  // the catch-up on what came meanwhile, where the first solve failed
  const std::vector<Key> expected = Keys(single.TakeEvents());
  ASSERT_EQ(expected.size(), 1u);
  EXPECT_EQ(Keys(live.TakeEvents()), expected);
  EXPECT_EQ(live.counters().samples, static_cast<long>(samples.size()));
}

TEST(LiveFrontEnd, ResetStartsAnAnchorOver) {
  LiveFrontEnd live(Chains, {});
  const std::vector<RangeSample> samples = AnchorSamples(2);
  for (const RangeSample& s : samples) live.AddSample(s);
  live.RunPendingSolves();
  const std::vector<FrontEndEvent> first = live.TakeEvents();
  ASSERT_FALSE(first.empty());
  EXPECT_FALSE(live.ResetAnchor(99));
  ASSERT_TRUE(live.ResetAnchor(2));
  EXPECT_TRUE(live.Inspect([](const FrontEnd& f) { return f.chains(2)[0].p_world_tag().empty(); }));
  for (const RangeSample& s : samples) live.AddSample(s);  // the same data again: the same events
  live.RunPendingSolves();
  EXPECT_EQ(Keys(live.TakeEvents()), Keys(first));
}

}  // namespace
}  // namespace anchorbench::estimator
