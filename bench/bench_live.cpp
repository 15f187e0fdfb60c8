// The live front end as the ROS node runs it (docs/ros.md): a feeder thread adds every pose and
// range of a hall log (8 anchors, 3 tags, 50 Hz a tag, every default trigger, the live work budget)
// while a solve worker steps as the node's does (20 Hz, at most 8 solves and 20 ms a step). For each
// event (an initialization or a certificate's evaluation) it measures the time from the range that
// made it due entering AddRange to the worker taking the event; for each range, AddRange's own
// time. Three paces: the log's own (1x), 10x, and as fast as the feeder can add (the sustained
// rate: every range added and every solve run). Writes one CSV row per pace.
//   bench_live [--out FILE] [--duration-s S]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/engine/attempt.hpp"
#include "anchorbench/estimator/live_front_end.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace ab = anchorbench;
using Clock = std::chrono::steady_clock;

namespace {

constexpr std::size_t kSolvesPerStep = 8;               // the node's defaults (ros/config/robot.yaml)
constexpr auto kStepPeriod = std::chrono::milliseconds(50);
constexpr auto kStepBudget = std::chrono::milliseconds(20);

std::string LogYaml(double duration_s) {
  return "seed: 7\n"
         "scenario:\n"
         "  environment: hall\n"
         "  tag_offsets_m: [[0, 0, 0], [0.3, 0, 0], [0, 0.3, 0.1]]\n"
         "  hall: {length_m: 20, width_m: 12, height_m: 6, num_anchors: 8, anchor_height_min_m: 0.5,"
         " anchor_height_max_m: 5.0, anchor_walls: all}\n"
         "  trajectory: {kind: random, height_m: 2.5, vertical_excursion_m: 1.5, rate_hz: 50, hall_duration_s: " +
         std::to_string(duration_s) +
         ", min_period_s: 15, max_period_s: 60}\n"
         "  ranging: {sigma_range_m: 0.1, outlier_probability: 0.02, max_range_m: 40}\n"
         "estimator: {nls: {max_passes: 200}}\n";  // the live front ends' budget
}

double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::nan("");
  const auto k = static_cast<std::size_t>(std::min<double>(values.size() - 1, std::floor(q * values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

struct PaceResult {
  std::string pace;
  std::size_t ranges = 0, events = 0, max_pending = 0;
  double wall_s = 0.0;
  std::vector<double> latency_ms, add_us;
};

// One run of the log through a fresh front end at `speed` x the log's rate (0: unpaced).
PaceResult RunPace(const std::string& name, double speed, const ab::sim::Scenario& log,
                   const ab::schema::ExperimentConfig& config, const ab::registry::Components& components) {
  ab::estimator::FrontEndOptions options;
  options.report_judgements = true;
  ab::estimator::LiveFrontEnd front_end(
      [&](int anchor_id) {
        return ab::registry::MakeChains(components, anchor_id, config.estimator,
                                        ab::engine::SolverSeed(config.seed, 0, anchor_id));
      },
      options);
  PaceResult result;
  result.pace = name;
  result.add_us.reserve(log.ranges.size());
  std::mutex mutex;  // guards entered: when the latest range of (anchor, time) entered AddRange
  std::map<std::pair<int, long long>, Clock::time_point> entered;
  const auto key = [](int anchor_id, double t_s) { return std::make_pair(anchor_id, std::llround(t_s * 1e6)); };
  std::atomic<bool> fed{false};

  std::thread worker([&] {
    for (;;) {
      const bool last = fed.load();
      const Clock::time_point start = Clock::now();
      result.max_pending = std::max(result.max_pending, front_end.pending_solves());
      front_end.RunPendingSolves(kSolvesPerStep, start + kStepBudget);
      const std::vector<ab::estimator::FrontEndEvent> events = front_end.TakeEvents();
      const Clock::time_point now = Clock::now();
      {
        std::lock_guard lock(mutex);
        for (const ab::estimator::FrontEndEvent& e : events) {
          const double t_s = e.kind == ab::estimator::FrontEndEvent::Kind::kJudged ? e.judgement.t_s : e.init.t_s;
          const auto found = entered.find(key(e.anchor_id, t_s));
          if (found == entered.end()) continue;
          result.latency_ms.push_back(std::chrono::duration<double, std::milli>(now - found->second).count());
        }
      }
      result.events += events.size();
      if (last && front_end.pending_solves() == 0) break;
      std::this_thread::sleep_until(start + kStepPeriod);
    }
  });

  const Clock::time_point start = Clock::now();
  std::size_t next = 0;
  for (std::size_t k = 0; k < log.t_s.size(); ++k) {
    if (speed > 0.0) {
      std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                                std::chrono::duration<double>((log.t_s[k] - log.t_s[0]) / speed)));
    }
    for (std::size_t tag = 0; tag < log.p_world_tag_reported.size(); ++tag) {
      front_end.AddPose(log.t_s[k], static_cast<int>(tag), log.p_world_tag_reported[tag][k]);
    }
    for (; next < log.ranges.size() && log.ranges[next].epoch == k; ++next) {
      const ab::sim::SimRange& r = log.ranges[next];
      const Clock::time_point in = Clock::now();
      {
        std::lock_guard lock(mutex);
        entered[key(r.anchor_id, r.t_s)] = in;
      }
      front_end.AddRange(r.t_s, r.tag_id, r.anchor_id, r.range_m);
      result.add_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - in).count());
    }
  }
  fed = true;
  worker.join();
  result.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  result.ranges = log.ranges.size();
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out;
  double duration_s = 60.0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--out") {
      out = argv[i + 1];
    } else if (flag == "--duration-s") {
      duration_s = std::stod(argv[i + 1]);
    } else {
      std::cerr << "bench_live: unknown option " << flag << " (--out FILE, --duration-s S)\n";
      return 2;
    }
  }
  ab::registry::Components components;
  ab::registry::RegisterBuiltins(components);
  const ab::schema::ExperimentConfig config = ab::config::LoadConfigText(LogYaml(duration_s), "bench_live", {}, components);
  const ab::sim::Scenario log = ab::sim::GenerateScenario(config.scenario, config.seed, 0);

  std::ofstream file;
  if (!out.empty()) file.open(out);
  std::ostream& csv = out.empty() ? std::cout : file;
  csv << "pace,anchors,tags,rate_hz,ranges,wall_s,ranges_per_s,events,latency_p50_ms,latency_p99_ms,latency_max_ms,"
         "add_first_us,add_p50_us,add_p99_us,add_max_us,max_pending_solves\n";
  for (const auto& [name, speed] : {std::pair{"1x", 1.0}, std::pair{"10x", 10.0}, std::pair{"unpaced", 0.0}}) {
    const PaceResult r = RunPace(name, speed, log, config, components);
    // The first range makes the first anchor's chains (and the kernel's table, once): apart.
    const std::vector<double> later_adds(r.add_us.begin() + 1, r.add_us.end());
    char line[512];
    std::snprintf(line, sizeof line, "%s,%zu,%zu,%g,%zu,%.3f,%.0f,%zu,%.2f,%.2f,%.2f,%.0f,%.2f,%.2f,%.1f,%zu\n",
                  r.pace.c_str(), log.anchors.size(), log.p_world_tag_reported.size(), config.scenario.trajectory.rate_hz,
                  r.ranges, r.wall_s, static_cast<double>(r.ranges) / r.wall_s, r.events, Quantile(r.latency_ms, 0.5),
                  Quantile(r.latency_ms, 0.99), Quantile(r.latency_ms, 1.0), r.add_us.front(), Quantile(later_adds, 0.5),
                  Quantile(later_adds, 0.99), Quantile(later_adds, 1.0), r.max_pending);
    csv << line;
    csv.flush();
  }
  return file.fail() ? 3 : 0;
}
