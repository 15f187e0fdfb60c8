#include "anchorbench/experiments/pdop_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/pdop.hpp"
#include "anchorbench/experiments/anchor_bank.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::experiments {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct RealizationResult {
  std::vector<PdopCheckpoint> checkpoints;
  UnderestimateStats stats;
};

RealizationResult StudyRealization(const ExperimentConfig& config, int realization, int every) {
  const sim::Scenario scenario = sim::GenerateScenario(config.scenario, config.seed, static_cast<std::uint64_t>(realization));
  const estimator::AnchorSolver solver(config.estimator.solver);
  RealizationResult result;
  for (const sim::SimAnchor& anchor : scenario.anchors) {
    // The online stage of the configured filter (a batch filter such as RANSAC accepts everything here).
    const std::unique_ptr<estimator::OutlierFilter> filter =
        BuiltinComponents().filters.Create(config.estimator.filter.kind, {config.estimator.filter, 0});
    estimator::ClosestPointPdop closest;
    estimator::TrueGeometry truth(anchor.p_world_anchor);
    std::vector<Eigen::Vector3d> p;
    std::vector<double> d;
    double t_first = 0.0;
    // Theorem 3.1's exact setting: the closest-point PDOP with the true distances, and its
    // precondition, rechecked over all samples when p_C moves (rare after the first seconds),
    // otherwise only for the new sample.
    estimator::ClosestPointPdop ideal;
    bool precondition = true;
    auto within = [&](const Eigen::Vector3d& q) {
      return (q - ideal.p_world_closest()).norm() <= (q - anchor.p_world_anchor).norm();
    };
    std::size_t epoch = 0;
    for (const sim::SimRange& range : scenario.ranges) {
      while (scenario.t_s[epoch] < range.t_s) ++epoch;
      if (range.anchor_id != anchor.id || !(range.range_m > 0.0)) continue;
      const Eigen::Vector3d& p_tag = scenario.p_world_tag_reported[static_cast<std::size_t>(range.tag_id)][epoch];
      if (!filter->Accept({range.t_s, range.tag_id, range.anchor_id, range.range_m, p_tag})) continue;
      if (p.empty()) t_first = range.t_s;
      p.push_back(p_tag);
      d.push_back(range.range_m);
      closest.Add(p_tag, range.range_m);
      truth.Add(p_tag);
      const Eigen::Vector3d p_closest_before = ideal.p_world_closest();
      ideal.Add(p_tag, (p_tag - anchor.p_world_anchor).norm());
      if (p.size() == 1 || ideal.p_world_closest() != p_closest_before) {
        precondition = std::all_of(p.begin(), p.end(), within);
      } else {
        precondition = precondition && within(p_tag);
      }

      const double estimate = closest.Value(), true_pdop = truth.Pdop();
      if (std::isfinite(estimate) && std::isfinite(true_pdop)) {
        UnderestimateStats& stats = result.stats;
        ++stats.samples;
        if (estimate < true_pdop) {
          ++stats.below;
          stats.ratios_below.push_back(estimate / true_pdop);
        }
        stats.worst_ratio = std::min(stats.worst_ratio, estimate / true_pdop);
        const bool ideal_below = ideal.Value() < true_pdop;
        stats.ideal_below += ideal_below;
        stats.ideal_samples_precondition += precondition;
        stats.ideal_below_precondition += precondition && ideal_below;
      }
      if (p.size() % static_cast<std::size_t>(every) != 0) continue;

      PdopCheckpoint c;
      c.realization = realization;
      c.anchor_id = anchor.id;
      c.n = static_cast<int>(p.size());
      c.t_s = range.t_s - t_first;
      c.pdop = {estimate, kInf, kInf, true_pdop};
      c.bias_aware_dop = truth.BiasAwareDop();
      const estimator::SolveResult ls = estimator::SolveDoubleDifferenceLs(p, d, config.estimator.solver.ls);
      if (estimator::Succeeded(ls.status)) {
        c.pdop[static_cast<int>(PdopMethod::kLs)] = estimator::GeometryPdop(p, d, ls.p_world_anchor);
        c.ls_error_m = (ls.p_world_anchor - anchor.p_world_anchor).norm();
        const estimator::SolveResult nls = solver.Solve(p, d);
        if (estimator::Succeeded(nls.status)) {
          c.pdop[static_cast<int>(PdopMethod::kNls)] = estimator::GeometryPdop(p, d, nls.p_world_anchor);
          c.nls_error_m = (nls.p_world_anchor - anchor.p_world_anchor).norm();
        }
      }
      result.checkpoints.push_back(c);
    }
  }
  return result;
}

}  // namespace

const char* PdopMethodName(PdopMethod method) {
  switch (method) {
    case PdopMethod::kClosestPoint: return "closest_point";
    case PdopMethod::kLs: return "ls";
    case PdopMethod::kNls: return "nls";
    case PdopMethod::kTrue: return "true";
  }
  return "unknown";
}

PdopStudy RunPdopStudy(const ExperimentConfig& config, int every, int threads) {
  std::vector<RealizationResult> per_realization(static_cast<std::size_t>(config.realizations));
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int r = 0; r < config.realizations; ++r) per_realization[static_cast<std::size_t>(r)] = StudyRealization(config, r, every);

  PdopStudy study;
  for (RealizationResult& r : per_realization) {
    for (PdopCheckpoint& c : r.checkpoints) study.checkpoints.push_back(c);
    study.stats.samples += r.stats.samples;
    study.stats.below += r.stats.below;
    study.stats.ideal_below += r.stats.ideal_below;
    study.stats.ideal_samples_precondition += r.stats.ideal_samples_precondition;
    study.stats.ideal_below_precondition += r.stats.ideal_below_precondition;
    study.stats.worst_ratio = std::min(study.stats.worst_ratio, r.stats.worst_ratio);
    study.stats.ratios_below.insert(study.stats.ratios_below.end(), r.stats.ratios_below.begin(),
                                    r.stats.ratios_below.end());
  }
  return study;
}

}  // namespace anchorbench::experiments
