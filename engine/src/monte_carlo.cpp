#include "anchorbench/engine/monte_carlo.hpp"

#include "anchorbench/config/load_config.hpp"

#include <omp.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <exception>
#include <map>
#include <stdexcept>

#include "anchorbench/engine/executor.hpp"
#include "anchorbench/engine/run_plan.hpp"
#include "anchorbench/estimator/front_end.hpp"
#include "anchorbench/eval/oracle_latency.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::engine {
namespace {

// The reported tag position of each range: the scenario's own epoch, no interpolation.
void SamplesOf(const sim::Scenario& scenario, std::vector<estimator::RangeSample>& samples) {
  samples.clear();
  samples.reserve(scenario.ranges.size());
  for (const sim::SimRange& range : scenario.ranges) {
    samples.push_back({range.t_s, range.tag_id, range.anchor_id, range.range_m,
                       scenario.p_world_tag_reported[static_cast<std::size_t>(range.tag_id)][range.epoch]});
  }
}

// One trigger over the realization: every anchor's initializer fed every sample, in one timed
// pass (no clock reads per sample). The attempts in anchor order; compute_s shared among them.
std::vector<schema::Attempt> RunTrigger(const schema::RowConfig& row, const std::string& trigger, std::uint64_t seed, int realization,
                                const registry::Components& components,
                                const std::map<int, schema::AnchorTruth>& truth,
                                const std::vector<estimator::RangeSample>& samples, double t_end_s) {
  estimator::FrontEnd front_end([&](int anchor_id) {
    const schema::AnchorTruth* known = TruthOf(&truth, anchor_id);
    std::vector<estimator::AnchorInitializer> chain;
    chain.push_back(registry::MakeInitializer(components, anchor_id, row.estimator, trigger,
                                              SolverSeed(seed, static_cast<std::uint64_t>(realization), anchor_id),
                                              known ? std::optional(known->p_world_anchor) : std::nullopt));
    return chain;
  });
  for (const auto& [anchor_id, anchor] : truth) front_end.AddAnchor(anchor_id);
  const auto start = std::chrono::steady_clock::now();
  for (const estimator::RangeSample& sample : samples) front_end.AddSample(sample);
  front_end.Finish(t_end_s);
  const double compute_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::map<int, estimator::InitEvent> events;
  for (const estimator::FrontEndEvent& event : front_end.TakeEvents()) events[event.anchor_id] = event.init;
  std::vector<schema::Attempt> attempts;
  const std::vector<int> anchor_ids = front_end.anchor_ids();
  for (int anchor_id : anchor_ids) {
    const auto event = events.find(anchor_id);
    attempts.push_back(AttemptOf(front_end.chains(anchor_id).front(),
                                 event == events.end() ? std::nullopt : std::optional(event->second), trigger,
                                 TruthOf(&truth, anchor_id)));
    attempts.back().compute_s = compute_s / static_cast<double>(anchor_ids.size());
  }
  return attempts;
}

// The oracle's time of every anchor (eval/oracle_latency.hpp): one more pass with the row's filter
// and solver, judged against the truth.
std::map<int, eval::OracleLatency> OracleLatencies(const schema::RowConfig& row, std::uint64_t seed, int realization,
                                                   const registry::Components& components,
                                                   const std::map<int, schema::AnchorTruth>& truth,
                                                   const std::vector<estimator::RangeSample>& samples, double t_end_s) {
  std::map<int, std::shared_ptr<eval::OracleLog>> logs;
  estimator::FrontEnd front_end([&](int anchor_id) {
    std::vector<estimator::AnchorInitializer> chain;
    const schema::AnchorTruth* known = TruthOf(&truth, anchor_id);
    if (!known) return chain;
    auto& log = logs[anchor_id] = std::make_shared<eval::OracleLog>();
    chain.push_back(eval::MakeOracleChain(components, anchor_id, row.estimator,
                                          SolverSeed(seed, static_cast<std::uint64_t>(realization), anchor_id),
                                          known->p_world_anchor, log));
    return chain;
  });
  for (const estimator::RangeSample& sample : samples) front_end.AddSample(sample);
  front_end.Finish(t_end_s);
  // The ideal region knows the row's white noise (not its outliers, biases or correlation).
  const eval::IdealRegion ideal{row.scenario.ranging.sigma_range_m, row.estimator.certificate.confidence};
  std::map<int, eval::OracleLatency> latencies;
  for (const auto& [anchor_id, log] : logs) {
    latencies[anchor_id] = eval::OracleOf(front_end.chains(anchor_id).front(), *log, row.estimator.certificate.accuracy_m,
                                          truth.at(anchor_id).p_world_anchor, t_end_s, ideal);
  }
  return latencies;
}

}  // namespace

int ResolveThreads(int requested) {
  const int cores = omp_get_num_procs();
  const int most = kThreadsPerCore * cores;
  const std::string limit = "at most " + std::to_string(most) + " (" + std::to_string(kThreadsPerCore) + " x the " +
                            std::to_string(cores) + " cores here)";
  if (requested > most) throw schema::InputError("--threads " + std::to_string(requested) + ": " + limit);
  if (requested > 0) return requested;
  if (const char* variable = std::getenv("OMP_NUM_THREADS")) {
    char* end = nullptr;
    const long from_environment = std::strtol(variable, &end, 10);  // "4" or the first level of "4,2"
    if (end == variable || (*end != '\0' && *end != ',') || from_environment < 1 || from_environment > most) {
      throw schema::InputError("OMP_NUM_THREADS=" + std::string(variable) + ": expected a thread count, " + limit);
    }
    return static_cast<int>(from_environment);
  }
  return cores;
}

void CheckWork(const schema::ExperimentConfig& config) {
  double attempts = 0.0;
  for (const schema::RowConfig& row : schema::RowsOf(config)) {
    attempts += static_cast<double>(config.realizations) * row.scenario.NumAnchors() *
                static_cast<double>(row.estimator.triggers.size());
  }
  if (attempts > kMaxAttemptsPerRun) {
    throw schema::InputError(config.name + ": " + std::to_string(static_cast<long long>(attempts)) +
                         " attempts (rows x realizations x anchors x triggers) in one run; at most 1e7: use fewer "
                         "realizations or split the rows");
  }
}

void CheckRows(const std::vector<schema::RowConfig>& rows, const registry::Components& components) {
  for (const schema::RowConfig& row : rows) {
    for (const std::string& trigger : row.estimator.triggers) {
      try {
        // A simulation knows every anchor's position: the stand-in gets one.
        registry::MakeInitializer(components, 0, row.estimator, trigger, 0, Eigen::Vector3d::Zero());
      } catch (const std::invalid_argument& e) {
        throw schema::InputError("row " + row.name + ": " + e.what());
      }
    }
  }
}

std::vector<schema::Attempt> RunRealization(const schema::RowConfig& row, int row_index, std::uint64_t seed, int realization,
                                    const registry::Components& components,
                                    std::vector<estimator::RangeSample>& samples) {
  const sim::Scenario scenario = sim::GenerateScenario(row.scenario, seed, static_cast<std::uint64_t>(realization));
  return RunRealization(row, row_index, seed, realization, scenario, components, samples);
}

std::vector<schema::Attempt> RunRealization(const schema::RowConfig& row, int row_index, std::uint64_t seed, int realization,
                                    const sim::Scenario& scenario, const registry::Components& components,
                                    std::vector<estimator::RangeSample>& samples) {
  std::map<int, schema::AnchorTruth> truth;
  for (const sim::SimAnchor& anchor : scenario.anchors) truth[anchor.id] = {anchor.p_world_anchor, anchor.bias_m};
  SamplesOf(scenario, samples);
  const double t_end_s = scenario.t_s.empty() ? 0.0 : scenario.t_s.back();

  std::vector<std::vector<schema::Attempt>> by_trigger;
  for (const std::string& trigger : row.estimator.triggers) {
    by_trigger.push_back(RunTrigger(row, trigger, seed, realization, components, truth, samples, t_end_s));
  }
  const std::map<int, eval::OracleLatency> oracle =
      row.estimator.oracle_latency ? OracleLatencies(row, seed, realization, components, truth, samples, t_end_s)
                                   : std::map<int, eval::OracleLatency>{};
  // Anchor by anchor, triggers in list order.
  std::vector<schema::Attempt> attempts;
  const double sigma_m = row.scenario.ranging.sigma_range_m;
  for (std::size_t a = 0; a < by_trigger.front().size(); ++a) {
    for (std::vector<schema::Attempt>& trigger_attempts : by_trigger) {
      schema::Attempt& attempt = trigger_attempts[a];
      attempt.row = row_index;
      attempt.realization = realization;
      if (const auto found = oracle.find(attempt.anchor_id); found != oracle.end()) AddOracleLatency(found->second, attempt);
      if (attempt.evaluation && attempt.evaluation->bias_aware_dop) {
        attempt.crlb_m = sigma_m * *attempt.evaluation->bias_aware_dop;
      }
      attempts.push_back(std::move(attempt));
    }
  }
  return attempts;
}

void CheckExperiment(const schema::ExperimentConfig& config, const registry::Components& components) {
  CheckWork(config);
  CheckRows(schema::RowsOf(config), components);
}

std::vector<schema::ExperimentConfig> SweepPoints(const config::ConfigDocument& document,
                                                  const std::vector<std::string>& overrides,
                                                  const std::vector<schema::SweepAxis>& axes,
                                                  std::optional<int> realizations,
                                                  const registry::Components& components) {
  std::vector<schema::ExperimentConfig> configs;
  for (const schema::SweepPoint& point : schema::SweepGrid(axes)) {
    std::vector<std::string> all = overrides;
    all.insert(all.end(), point.overrides.begin(), point.overrides.end());
    schema::ExperimentConfig config = config::LoadConfig(document, all, components);
    if (realizations) config.realizations = *realizations;
    CheckExperiment(config, components);
    configs.push_back(std::move(config));
  }
  return configs;
}

std::vector<schema::Attempt> RunMonteCarlo(const schema::ExperimentConfig& config, const registry::Components& components,
                                           const MonteCarloOptions& options) {
  CheckExperiment(config, components);
  const Plan plan({config});
  LocalExecutor executor(components);
  std::map<int, ChunkResult> chunks = RunPlan(plan, executor, {options.threads, nullptr, options.progress, {}});
  return std::move(Join(plan, chunks).front().attempts);
}

}  // namespace anchorbench::engine
