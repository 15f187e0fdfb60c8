#include "anchorbench/studies/pdop_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include <sstream>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/front_end.hpp"
#include "anchorbench/estimator/pdop.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/eval/true_geometry.hpp"
#include "anchorbench/report/pdop_study_report.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/engine/attempt.hpp"
#include "anchorbench/engine/unit_records.hpp"
#include "anchorbench/sim/scenario.hpp"
#include "pdop_lines.hpp"

namespace anchorbench::studies {

using engine::RunControl;
using engine::RunUnitRecords;
using engine::Shard;
using engine::SolverSeed;
using engine::UnitRecords;
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// What one anchor's probe collects.
struct AnchorStudy {
  std::vector<schema::PdopCheckpoint> checkpoints;
  schema::UnderestimateStats stats;
  double t_first_s = 0.0;  // the anchor's first accepted sample
};

// In the trigger's place, never firing: it sees every accepted sample with the closest-point PDOP
// the initializer keeps, and measures it against the truth; every `every` samples it solves (LS,
// then LS + the configured NLS) on the data so far.
class StudyProbe : public estimator::InitTrigger {
 public:
  StudyProbe(const sim::SimAnchor& anchor, int realization, int every, const estimator::LsOptions& ls,
             double confidence_sigmas, std::shared_ptr<const estimator::Solver> solver, AnchorStudy* out)
      : anchor_(anchor), realization_(realization), every_(static_cast<std::size_t>(every)), ls_(ls),
        confidence_sigmas_(confidence_sigmas), solver_(std::move(solver)), truth_(anchor.p_world_anchor), out_(out) {}

  bool Fire(const estimator::TriggerInput& in) override {
    out_->t_first_s = in.t_first_s;
    truth_.Add(in.sample_p_world_tag);
    measured_.Add(in.sample_p_world_tag, in.sample_range_m);
    UpdateIdeal(in);
    CountUnderestimate(in.pdop);
    if (in.n_admitted % every_ == 0) out_->checkpoints.push_back(Checkpoint(in));
    return false;
  }

 private:
  // Theorem 3.1's exact setting: the closest-point PDOP with the true distances, and its
  // precondition, rechecked over all samples when p_C moves (rare after the first seconds),
  // otherwise only for the new sample.
  void UpdateIdeal(const estimator::TriggerInput& in) {
    auto within = [&](const Eigen::Vector3d& q) {
      return (q - ideal_.p_world_closest()).norm() <= (q - anchor_.p_world_anchor).norm();
    };
    const Eigen::Vector3d p_closest_before = ideal_.p_world_closest();
    ideal_.Add(in.sample_p_world_tag, (in.sample_p_world_tag - anchor_.p_world_anchor).norm());
    if (in.n_admitted == 1 || ideal_.p_world_closest() != p_closest_before) {
      precondition_ = std::all_of(in.p_world_tag.begin(), in.p_world_tag.end(), within);
    } else {
      precondition_ = precondition_ && within(in.sample_p_world_tag);
    }
  }

  void CountUnderestimate(double estimate) {
    const double true_pdop = truth_.Pdop();
    if (!std::isfinite(estimate) || !std::isfinite(true_pdop)) return;
    schema::UnderestimateStats& stats = out_->stats;
    ++stats.samples;
    if (estimate < true_pdop) {
      ++stats.below;
      stats.ratios_below.push_back(estimate / true_pdop);
    }
    stats.worst_ratio = std::min(stats.worst_ratio, estimate / true_pdop);
    const bool ideal_below = ideal_.Value() < true_pdop;
    stats.ideal_below += ideal_below;
    stats.ideal_samples_precondition += precondition_;
    stats.ideal_below_precondition += precondition_ && ideal_below;
  }

  schema::PdopCheckpoint Checkpoint(const estimator::TriggerInput& in) const {
    schema::PdopCheckpoint c;
    c.realization = realization_;
    c.anchor_id = anchor_.id;
    c.n = static_cast<int>(in.n_admitted);
    c.t_s = in.t_s - in.t_first_s;
    c.pdop = {in.pdop, kInf, kInf, truth_.Pdop()};
    c.bias_aware_dop = truth_.BiasAwareDop();
    c.dop4_closest_point = measured_.BiasAwareValue();
    c.dop4_confidence = kInf;
    const estimator::SolveResult ls = estimator::SolveDoubleDifferenceLs(in.p_world_tag, in.range_m, ls_);
    if (!estimator::Succeeded(ls.status)) return c;
    c.pdop[static_cast<int>(schema::PdopMethod::kLs)] = estimator::GeometryPdop(in.p_world_tag, in.range_m, ls.p_world_anchor);
    c.ls_error_m = (ls.p_world_anchor - anchor_.p_world_anchor).norm();
    const estimator::SolveResult nls = solver_->Solve(in.p_world_tag, in.range_m);
    if (estimator::Succeeded(nls.status)) {
      c.pdop[static_cast<int>(schema::PdopMethod::kNls)] = estimator::GeometryPdop(in.p_world_tag, in.range_m, nls.p_world_anchor);
      c.nls_error_m = (nls.p_world_anchor - anchor_.p_world_anchor).norm();
      c.dop4_confidence = estimator::WorstBiasAwareDop(in.p_world_tag, nls, confidence_sigmas_);
    }
    return c;
  }

  sim::SimAnchor anchor_;
  int realization_;
  std::size_t every_;
  estimator::LsOptions ls_;
  double confidence_sigmas_;
  std::shared_ptr<const estimator::Solver> solver_;
  eval::TrueGeometry truth_;
  estimator::ClosestPointPdop ideal_;
  estimator::ClosestPointPdop measured_;  // as the initializer keeps it (a trigger does not see those sums)
  bool precondition_ = true;
  AnchorStudy* out_;
};

// The certified chain's event (or refusal) per anchor, measured against the truth.
std::vector<schema::CertifiedOutcome> CertifiedOutcomes(const sim::Scenario& scenario, estimator::FrontEnd& front_end,
                                                const std::map<int, AnchorStudy>& by_anchor, int realization) {
  std::map<int, estimator::InitEvent> fired;
  for (const estimator::FrontEndEvent& event : front_end.TakeEvents()) {
    if (event.chain == 1) fired[event.anchor_id] = event.init;
  }
  std::vector<schema::CertifiedOutcome> outcomes;
  for (const sim::SimAnchor& anchor : scenario.anchors) {
    schema::CertifiedOutcome o;
    o.realization = realization;
    o.anchor_id = anchor.id;
    o.status = "waiting";
    if (const auto it = fired.find(anchor.id); it != fired.end()) {
      const estimator::InitEvent& event = it->second;
      o.t_s = event.t_s - by_anchor.at(anchor.id).t_first_s;
      o.n = event.n_used;
      o.status = estimator::ToString(event.solve.status);
      if (estimator::Succeeded(event.solve.status)) o.error_m = (event.solve.p_world_anchor - anchor.p_world_anchor).norm();
    } else if (const auto refusal = front_end.chains(anchor.id).at(1).trigger_refusal()) {
      o.status = estimator::ToString(*refusal);
    }
    outcomes.push_back(std::move(o));
  }
  return outcomes;
}

schema::PdopStudy StudyRealization(const schema::ExperimentConfig& config, const registry::Components& components, int realization,
                           int every) {
  const sim::Scenario scenario =
      sim::GenerateScenario(config.scenario, config.seed, static_cast<std::uint64_t>(realization));
  const schema::EstimatorConfig& estimator = config.estimator;
  const auto solver = std::make_shared<estimator::AnchorSolver>(
      estimator.solver_options, components.tables->Get(estimator.solver_options.nls.truncation,
                                                        estimator.solver_options.nls.alpha_min));
  std::map<int, AnchorStudy> by_anchor;
  estimator::FrontEnd front_end([&](int anchor_id) {
    const sim::SimAnchor& anchor = scenario.anchors[static_cast<std::size_t>(anchor_id)];
    const std::uint64_t seed = SolverSeed(config.seed, static_cast<std::uint64_t>(realization), anchor_id);
    // The configured chain with the probe in the trigger's place (its filter's online stage: a
    // batch filter such as RANSAC accepts everything here), and the certified chain beside it.
    const registry::TriggerMaker probe = [&](const registry::TriggerContext&, std::string*) {
      return std::make_unique<StudyProbe>(anchor, realization, every, estimator.solver_options.ls,
                                          estimator.trigger.confidence_sigmas, solver, &by_anchor[anchor_id]);
    };
    std::vector<estimator::AnchorInitializer> chain;
    chain.push_back(registry::MakeInitializer(components, anchor_id, estimator, probe, seed, anchor.p_world_anchor));
    chain.push_back(registry::MakeInitializer(components, anchor_id, estimator, "certified", seed, anchor.p_world_anchor));
    return chain;
  });
  for (const sim::SimAnchor& anchor : scenario.anchors) front_end.AddAnchor(anchor.id);
  for (const sim::SimRange& range : scenario.ranges) {
    front_end.AddSample({range.t_s, range.tag_id, range.anchor_id, range.range_m,
                         scenario.p_world_tag_reported[static_cast<std::size_t>(range.tag_id)][range.epoch]});
  }
  schema::PdopStudy study;
  study.anchors = static_cast<int>(scenario.anchors.size());
  for (auto& [anchor_id, anchor] : by_anchor) {
    study.checkpoints.insert(study.checkpoints.end(), anchor.checkpoints.begin(), anchor.checkpoints.end());
    study.stats.Add(anchor.stats);
  }
  study.certified = CertifiedOutcomes(scenario, front_end, by_anchor, realization);
  return study;
}

}  // namespace

schema::PdopStudyConfig PdopStudyOf(const schema::ExperimentConfig& config) {
  return config.pdop_study.value_or(schema::PdopStudyConfig{});
}

void CheckPdopStudy(const schema::ExperimentConfig& config, const registry::Components& components) {
  std::string why;
  if (!components.filters.Knows(config.estimator.filter.kind, &why)) throw schema::InputError(why);
  const double anchors = static_cast<double>(config.realizations) * config.scenario.NumAnchors();
  if (anchors > 1e6) throw schema::InputError(config.name + ": realizations x anchors above 1e6 for a PDOP study");
}

UnitRecords<schema::PdopStudy> PdopStudyUnits(const schema::ExperimentConfig& config,
                                              const registry::Components& components) {
  UnitRecords<schema::PdopStudy> units;  // a unit is a realization of the base scenario
  units.units = config.realizations;
  units.compute = [config, every = PdopStudyOf(config).every, &components](int r) {
    return std::vector<schema::PdopStudy>{StudyRealization(config, components, r, every)};
  };
  units.text = PdopUnitText;
  units.read = ReadPdopUnit;
  return units;
}

std::vector<schema::PdopStudy> RunPdopStudy(const schema::ExperimentConfig& config,
                                            const registry::Components& components, int threads,
                                            const RunControl& control) {
  CheckPdopStudy(config, components);
  return RunUnitRecords(PdopStudyUnits(config, components), threads, Shard{}, control, nullptr);
}

schema::PdopStudy JoinPdopStudy(const std::vector<schema::PdopStudy>& realizations) {
  schema::PdopStudy study;
  for (const schema::PdopStudy& r : realizations) {
    study.checkpoints.insert(study.checkpoints.end(), r.checkpoints.begin(), r.checkpoints.end());
    study.certified.insert(study.certified.end(), r.certified.begin(), r.certified.end());
    study.stats.Add(r.stats);
    study.anchors += r.anchors;
  }
  return study;
}

std::string WritePdopStudyFiles(const engine::FileWriter& write, const schema::ExperimentConfig& config,
                                const std::vector<schema::PdopStudy>& realizations, const report::RunInfo& info) {
  const schema::PdopStudy study = JoinPdopStudy(realizations);
  const schema::PdopStudyConfig settings = PdopStudyOf(config);
  write("pdop_trace.csv", [&](std::ostream& file) { report::WritePdopTrace(file, study.checkpoints); });
  std::ostringstream md;
  report::WritePdopStudyMarkdown(md, config, study, settings.every, settings.bin_s);
  write("pdop_study.md", [&](std::ostream& file) { file << md.str(); });
  write("manifest.json", [&](std::ostream& file) { file << report::ManifestJson(config, info); });
  return md.str();
}

}  // namespace anchorbench::studies
