// The online front end as a navigation stack runs it: one simulated tunnel drive past 30 anchors,
// every range fed one at a time. Reports the cost per fed range, everything included (pose
// interpolation, the consistency check, the closest-point PDOP, the trigger, and the solves when
// anchors initialize), with the paper's chain per anchor.
#include <benchmark/benchmark.h>

#include "anchorbench/estimator/front_end.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace {

namespace est = anchorbench::estimator;
namespace sim = anchorbench::sim;

const sim::Scenario& Drive() {
  static const sim::Scenario scenario = [] {
    sim::ScenarioOptions options;  // the default tunnel: 300 m, 30 anchors, 10 Hz
    options.ranging.outlier_probability = 0.02;
    return sim::GenerateScenario(options, 1, 0);
  }();
  return scenario;
}

est::FrontEnd PaperFrontEnd(bool defer) {
  auto tables = std::make_shared<est::LogPartitionTables>();
  est::FrontEndOptions options;
  options.defer_solves = defer;
  return est::FrontEnd(
      [tables](int anchor_id) {
        std::vector<est::AnchorInitializer> chains;
        chains.push_back(est::MakePaperInitializer(anchor_id, {}, tables->Get(10.0, -10.0)));
        return chains;
      },
      options);
}

// Ranges with their tag position known (as the Monte Carlo runner feeds them).
void BM_FrontEndPerSample(benchmark::State& state) {
  const sim::Scenario& drive = Drive();
  for (auto _ : state) {
    est::FrontEnd front_end = PaperFrontEnd(false);
    for (const sim::SimRange& r : drive.ranges) {
      front_end.AddSample({r.t_s, r.tag_id, r.anchor_id, r.range_m, drive.p_world_tag_reported[0][r.epoch]});
    }
    front_end.Finish(drive.t_s.back());
    benchmark::DoNotOptimize(front_end.TakeEvents());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(drive.ranges.size()));
}

// Poses and ranges as a sensor callback gets them (poses at 10 Hz, interpolated), solves
// deferred and run after every epoch.
void BM_FrontEndPerRangeWithPoses(benchmark::State& state) {
  const sim::Scenario& drive = Drive();
  for (auto _ : state) {
    est::FrontEnd front_end = PaperFrontEnd(true);
    std::size_t next = 0;
    for (std::size_t k = 0; k < drive.t_s.size(); ++k) {
      front_end.AddPose(drive.t_s[k], 0, drive.p_world_tag_reported[0][k]);
      for (; next < drive.ranges.size() && drive.ranges[next].epoch == k; ++next) {
        const sim::SimRange& r = drive.ranges[next];
        front_end.AddRange(r.t_s, r.tag_id, r.anchor_id, r.range_m);
      }
      front_end.RunPendingSolves();
    }
    front_end.Finish(drive.t_s.back());
    benchmark::DoNotOptimize(front_end.TakeEvents());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(drive.ranges.size()));
}

BENCHMARK(BM_FrontEndPerSample)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrontEndPerRangeWithPoses)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
