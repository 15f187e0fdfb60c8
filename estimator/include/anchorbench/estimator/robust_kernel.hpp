#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

namespace nlopt {
class opt;
}

namespace anchorbench::estimator {

// Barron's general loss, Eq. (13), on the normalized residual x = r / c:
//   rho(x, alpha) = |alpha-2|/alpha * ((x^2/|alpha-2| + 1)^(alpha/2) - 1)
// with the exact limits alpha = 2 (x^2/2, L2) and alpha = 0 (log(x^2/2 + 1), Cauchy).
double Rho(double x, double alpha);

// IRLS weight rho'(x)/x = (x^2/|alpha-2| + 1)^(alpha/2 - 1); in units of the residual r the
// weight is this divided by c^2. Limits: 1 (alpha = 2), 2/(x^2 + 2) (alpha = 0).
double Weight(double x, double alpha);

// Both at once, sharing the one log1p they need (the solver's inner loop).
struct KernelValue {
  double rho;
  double weight;
};
KernelValue EvaluateKernel(double x, double alpha);

// log Z~(alpha) with Z~(alpha) = integral of exp(-rho(x, alpha)) over |x| <= truncation: the
// normalizer of the truncated density exp(-rho(r/c, alpha)) / (c Z~(alpha)) of Chebrolu et al.
// (RA-L 2021). For alpha < 0 the untruncated integral diverges, so the truncation decides how
// readily negative alphas are chosen. Tabulated once on a fine alpha grid (Simpson's rule) and
// interpolated linearly; immutable after construction.
class LogPartitionTable {
 public:
  LogPartitionTable(double truncation, double alpha_min);

  double LogZ(double alpha) const;
  double truncation() const { return truncation_; }
  double alpha_min() const { return alpha_min_; }

  // Direct numerical integral, for tests and for building the table.
  static double IntegrateZ(double alpha, double truncation);

 private:
  double truncation_;
  double alpha_min_;
  double alpha_step_;
  std::vector<double> log_z_;
};

// Tables by (truncation, alpha_min), each built on first request (~40 ms) and then shared by every
// solver that asks. Owned by whoever builds the solvers (the registry's Components, or your code):
// no process-wide state. Thread-safe.
class LogPartitionTables {
 public:
  std::shared_ptr<const LogPartitionTable> Get(double truncation, double alpha_min);

 private:
  std::mutex mutex_;
  std::vector<std::shared_ptr<const LogPartitionTable>> tables_;
};

// Chooses the kernel shape alpha in [alpha_min, 2] by minimizing the negative log-likelihood of
// the residuals under the truncated density (Eq. (12); Chebrolu et al. 2021):
//   NLL(alpha) = N log Z~(alpha) + sum_i rho(r_i / c, alpha)      (+ N log c, constant in alpha)
// The residuals are summarized in kBins bins evenly spaced in log(1 + |x|) up to kMaxAbsX (larger
// values share the last bin); each bin keeps its count and the mean of x^2, so one NLL evaluation
// costs kBins kernel evaluations instead of N. The truncation only normalizes the density;
// residuals beyond it still count with their rho.
class AlphaSelector {
 public:
  static constexpr int kBins = 48;
  static constexpr double kMaxAbsX = 1e3;
  static constexpr double kAlphaTolerance = 1e-2;  // NLopt's x tolerance on alpha

  explicit AlphaSelector(std::shared_ptr<const LogPartitionTable> table);
  ~AlphaSelector();
  AlphaSelector(const AlphaSelector&) = delete;
  AlphaSelector& operator=(const AlphaSelector&) = delete;

  void Clear();
  void Add(double x);  // one normalized residual r / c
  // argmin NLL over [alpha_min, 2]: a coarse grid plus NLopt refinement, or, given the previous
  // iteration's alpha, NLopt refinement from there. Not const: it sets the optimizer's bounds.
  double Select(std::optional<double> previous_alpha = std::nullopt);
  double Nll(double alpha) const;  // from the histogram: what Select minimizes
  // NLL evaluated exactly on residuals, for tests.
  static double ExactNll(std::span<const double> x, double alpha, const LogPartitionTable& table);

 private:
  std::shared_ptr<const LogPartitionTable> table_;
  // Built once per selector and reused by every Select (one per LM iteration); NLopt itself still
  // allocates its workspace inside each optimize call.
  std::unique_ptr<nlopt::opt> optimizer_;
  std::array<double, kBins> bin_count_{};
  std::array<double, kBins> bin_sum_x_squared_{};
  double total_count_ = 0.0;
};

}  // namespace anchorbench::estimator
