#pragma once
// The oracle's time (ours, docs/method.md#latency-against-an-oracle): for one anchor, the earliest
// time after which the running fit stays within D of the true anchor. The fit is the anchor's own
// (its solver, with its tags' offsets as the initializer solves them) on the samples its filter
// accepted so far, judged on a geometric cadence and on all of the data at the end; the truth only
// judges. A trigger that fires at the oracle's time is as early as the data allow: the figure a
// certificate is measured by (t_init / t_oracle, both from the anchor's first accepted sample).

#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/registry/components.hpp"

namespace anchorbench::eval {

struct OracleLatency {
  double t_first_s = 0.0;            // the anchor's first accepted sample
  std::optional<double> t_oracle_s;  // none: the fit on all of the data is farther than D (no certificate can be right)
  std::optional<double> t_ideal_s;   // IdealRegionTime on the same samples, where the noise is known
};

// The ideal certificate's region (ours, docs/method.md#latency-against-an-oracle): what a region
// test would need if it knew the truth's geometry and white range noise of sigma_range_m, with
// the bias as the one other unknown (Eq. (1)).
struct IdealRegion {
  double sigma_range_m = 0.0;
  double confidence = 0.99;  // the certificate's
};

// What the oracle's chain saw: the time of every sample it admitted, its evaluations (the
// samples then, the error of the fit), in order, and the solve it judges (the anchor's solver and
// tags' offsets, as its trigger got them).
struct OracleLog {
  double t_first_s = 0.0;
  std::vector<double> t_admitted_s;
  struct Evaluation {
    std::size_t samples;
    double t_s;
    double error_m;  // |fit - truth|, +inf where the solve failed
  };
  std::vector<Evaluation> evaluations;
  std::shared_ptr<const estimator::Solver> solver;
  estimator::TagBiasOptions tags;
};

// The oracle's coarse cadence: an evaluation each time the samples grew by half; then, between
// the last evaluation beyond D and the next, the first sample count within D is bisected to 1/64 of
// that interval (ours: its time to within about 1%, at about the cost of five solves on all of the
// data per anchor; the bisection takes the error as monotone in between).
inline constexpr double kOracleGrowth = 1.5;
inline constexpr int kOracleBisections = 6;

// The oracle's chain for an anchor: the config's filter and solver, a trigger that never fires and
// logs the fit's error into `log` on its cadence.
estimator::AnchorInitializer MakeOracleChain(const registry::Components& components, int anchor_id,
                                             const schema::EstimatorConfig& config, std::uint64_t seed,
                                             const Eigen::Vector3d& p_world_anchor, std::shared_ptr<OracleLog> log);

// The time from the chain (its buffer: all the accepted data, at the end) and its log; D is the
// certificate's accuracy_m. With `ideal` (a simulation, whose noise is known), also the ideal
// region's time on the same samples.
OracleLatency OracleOf(const estimator::AnchorInitializer& chain, const OracleLog& log, double accuracy_m,
                       const Eigen::Vector3d& p_world_anchor, double t_end_s,
                       const std::optional<IdealRegion>& ideal = std::nullopt);

// The earliest accepted sample from which the ideal region's `confidence` ellipsoid, the Cramer-Rao
// bound at the true anchor (TrueGeometry: sigma^2 (sum (u - u_mean)(u - u_mean)^T)^-1), lies
// within D: chi2_3(confidence) sigma^2 lambda_max <= D^2. It only shrinks as samples come, so the
// first such sample is bisected. None if all of the samples do not get there. Where the noise is
// white and the bias the only nuisance, no honest region of that confidence is smaller (an efficient
// estimator's), so t_ideal / t_oracle is the latency the confidence itself costs, whatever the
// certificate; a real radio's correlated noise, biases and offsets only make the honest region larger.
std::optional<double> IdealRegionTime(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> t_s,
                                      const Eigen::Vector3d& p_world_anchor, double accuracy_m,
                                      const IdealRegion& ideal);

// (t_init - t_first) / (t_oracle - t_first): how much later than the data allowed; none where the
// oracle has no time or the attempt no initialization. With t_ideal for t_init: the ideal region's.
std::optional<double> LatencyRatio(const OracleLatency& oracle, std::optional<double> t_init_s);

}  // namespace anchorbench::eval
