#include "anchorbench/eval/oracle_latency.hpp"

#include <limits>

#include "anchorbench/estimator/tag_biases.hpp"
#include "anchorbench/estimator/triggers.hpp"

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
                       const Eigen::Vector3d& p_world_anchor, double t_end_s) {
  OracleLatency out;
  out.t_first_s = log.t_first_s;
  if (chain.range_m().empty() || !log.solver) return out;
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
  // Bisected between them, where the buffer holds every admitted sample (no thinning at its cap).
  const bool whole = log.t_admitted_s.size() == n;
  for (int step = 0; whole && bad > 0 && step < kOracleBisections && good - bad > 1; ++step) {
    const std::size_t mid = bad + (good - bad) / 2;
    const double error_m = FitError(*log.solver, chain.p_world_tag().first(mid), chain.range_m().first(mid),
                                    chain.tag_id().first(mid), log.tags, p_world_anchor);
    (error_m <= d_m ? good : bad) = mid;
  }
  out.t_oracle_s = whole ? log.t_admitted_s[good - 1] : t_good_s;
  return out;
}

std::optional<double> LatencyRatio(const OracleLatency& oracle, std::optional<double> t_init_s) {
  if (!oracle.t_oracle_s || !t_init_s) return std::nullopt;
  const double allowed_s = *oracle.t_oracle_s - oracle.t_first_s;
  if (!(allowed_s > 0.0)) return std::nullopt;
  return (*t_init_s - oracle.t_first_s) / allowed_s;
}

}  // namespace anchorbench::eval
