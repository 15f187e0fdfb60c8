#include "anchorbench/eval/oracle_latency.hpp"

#include <algorithm>
#include <limits>

#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/estimator/tag_biases.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/eval/true_geometry.hpp"

namespace anchorbench::eval {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double FitError(const estimator::Solver& solver, std::span<const Eigen::Vector3d> p_world_tag,
                std::span<const double> range_m, std::span<const int> tag_id, const estimator::TagBiasOptions& tags,
                const Eigen::Vector3d& p_world_anchor) {
  const estimator::SolveResult fit = estimator::SolveWithTagBiases(solver, p_world_tag, range_m, tag_id, tags);
  return estimator::Succeeded(fit.status) ? (fit.p_world_anchor - p_world_anchor).norm() : kInf;
}

// Never fires; on its cadence, logs how far the running fit is from the truth.
class OracleProbe final : public estimator::InitTrigger {
 public:
  OracleProbe(std::shared_ptr<const estimator::Solver> solver, estimator::TagBiasOptions tags,
              const Eigen::Vector3d& p_world_anchor, std::shared_ptr<OracleLog> log)
      : solver_(std::move(solver)), tags_(tags), p_world_anchor_(p_world_anchor), log_(std::move(log)),
        cadence_(1, kOracleGrowth) {}
  bool Fire(const estimator::TriggerInput& in) override {
    log_->t_first_s = in.t_first_s;
    log_->t_admitted_s.push_back(in.t_s);
    return cadence_.Due(in);
  }
  bool Evaluate(const estimator::TriggerInput& in) override {
    log_->evaluations.push_back(
        {in.range_m.size(), in.t_s, FitError(*solver_, in.p_world_tag, in.range_m, in.tag_id, tags_, p_world_anchor_)});
    return false;
  }

 private:
  std::shared_ptr<const estimator::Solver> solver_;
  estimator::TagBiasOptions tags_;
  Eigen::Vector3d p_world_anchor_;
  std::shared_ptr<OracleLog> log_;
  estimator::SolveCadence cadence_;
};

}  // namespace

estimator::AnchorInitializer MakeOracleChain(const registry::Components& components, int anchor_id,
                                             const schema::EstimatorConfig& config, std::uint64_t seed,
                                             const Eigen::Vector3d& p_world_anchor, std::shared_ptr<OracleLog> log) {
  return registry::MakeInitializer(
      components, anchor_id, config,
      [&](const registry::TriggerContext& context, std::string*) -> std::unique_ptr<estimator::InitTrigger> {
        log->solver = context.solver;
        log->tags = context.initializer.tag_biases;
        return std::make_unique<OracleProbe>(context.solver, context.initializer.tag_biases, p_world_anchor, log);
      },
      seed, p_world_anchor);
}

OracleLatency OracleOf(const estimator::AnchorInitializer& chain, const OracleLog& log, double accuracy_m,
                       const Eigen::Vector3d& p_world_anchor, double t_end_s, const std::optional<IdealRegion>& ideal) {
  OracleLatency out;
  out.t_first_s = log.t_first_s;
  if (chain.range_m().empty() || !log.solver) return out;
  // The buffer holds every admitted sample (no thinning at its cap): their times are the log's.
  const bool whole = log.t_admitted_s.size() == chain.range_m().size();
  if (ideal && whole) out.t_ideal_s = IdealRegionTime(chain.p_world_tag(), log.t_admitted_s, p_world_anchor, accuracy_m, *ideal);
  // The fit on all of the data, as the chain's trigger would have solved it.
  const double d_m = accuracy_m;
  const double final_error_m =
      FitError(*log.solver, chain.p_world_tag(), chain.range_m(), chain.tag_id(), log.tags, p_world_anchor);
  if (!(final_error_m <= d_m)) return out;
  // The last evaluation beyond D, and the first after it within D (or all of the data).
  const std::size_t n = chain.range_m().size();
  std::size_t bad = 0, good = n;
  double t_good_s = t_end_s;
  for (auto it = log.evaluations.rbegin(); it != log.evaluations.rend(); ++it) {
    if (!(it->error_m <= d_m)) {
      bad = it->samples;
      break;
    }
    good = it->samples;
    t_good_s = it->t_s;
  }
  // Bisected between them, where the buffer holds every admitted sample.
  for (int step = 0; whole && bad > 0 && step < kOracleBisections && good - bad > 1; ++step) {
    const std::size_t mid = bad + (good - bad) / 2;
    const double error_m = FitError(*log.solver, chain.p_world_tag().first(mid), chain.range_m().first(mid),
                                    chain.tag_id().first(mid), log.tags, p_world_anchor);
    (error_m <= d_m ? good : bad) = mid;
  }
  out.t_oracle_s = whole ? log.t_admitted_s[good - 1] : t_good_s;
  return out;
}

std::optional<double> IdealRegionTime(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> t_s,
                                      const Eigen::Vector3d& p_world_anchor, double accuracy_m,
                                      const IdealRegion& ideal) {
  // Within D once the least information reaches chi2 sigma^2 / D^2 (lambda_max = 1 / its least).
  const double needed = estimator::ChiSquare3Quantile(ideal.confidence) * ideal.sigma_range_m * ideal.sigma_range_m /
                        (accuracy_m * accuracy_m);
  const auto within = [&](const TrueGeometry& geometry) { return geometry.BiasAwareLeastInformation() >= needed; };
  // One pass, judged on a geometric cadence (and at the end): the last count outside, the first inside.
  const std::size_t n = std::min(p_world_tag.size(), t_s.size());
  TrueGeometry geometry(p_world_anchor), at_outside(p_world_anchor);
  std::size_t outside = 0, inside = 0, next = 1;
  for (std::size_t k = 0; k < n && inside == 0; ++k) {
    geometry.Add(p_world_tag[k]);
    if (k + 1 < next && k + 1 < n) continue;
    if (within(geometry)) {
      inside = k + 1;
    } else {
      outside = k + 1;
      at_outside = geometry;
      next = std::max(k + 2, static_cast<std::size_t>(kOracleGrowth * static_cast<double>(k + 1)));
    }
  }
  if (inside == 0) return std::nullopt;
  // Bisected between them, from the geometry at the count outside.
  while (inside - outside > 1) {
    const std::size_t mid = outside + (inside - outside) / 2;
    TrueGeometry probe = at_outside;
    for (std::size_t k = outside; k < mid; ++k) probe.Add(p_world_tag[k]);
    if (within(probe)) {
      inside = mid;
    } else {
      outside = mid;
      at_outside = probe;
    }
  }
  return t_s[inside - 1];
}

std::optional<double> LatencyRatio(const OracleLatency& oracle, std::optional<double> t_init_s) {
  if (!oracle.t_oracle_s || !t_init_s) return std::nullopt;
  const double allowed_s = *oracle.t_oracle_s - oracle.t_first_s;
  if (!(allowed_s > 0.0)) return std::nullopt;
  return (*t_init_s - oracle.t_first_s) / allowed_s;
}

}  // namespace anchorbench::eval
