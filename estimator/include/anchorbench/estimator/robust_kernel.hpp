#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

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

// Up to kChunk values in storage of their own (Eigen's fixed maximum size: no heap), small enough
// that a chunk's arrays stay in the L1 cache: the unit of the vectorized passes over samples.
constexpr int kChunk = 256;
using Chunk = Eigen::Array<double, Eigen::Dynamic, 1, Eigen::ColMajor, kChunk, 1>;

// The kernel on up to kChunk residuals at once, vectorized: Eigen's SIMD log and exp instead of
// two libm calls per residual. Agrees with the scalar form to 1e-13 relative plus 1e-15 absolute
// (base^(alpha/2) - 1 cancels in both; a test checks over alpha in [-10, 2] and residuals from
// 1e-8 to 1e4).
class KernelArrays {
 public:
  void Evaluate(const Chunk& x, double alpha);
  const Chunk& rho() const { return rho_; }
  const Chunk& weight() const { return weight_; }

 private:
  Chunk u_;         // x^2/|alpha-2|
  Chunk base_;      // u + 1
  Chunk log_base_;  // log1p(x^2/|alpha-2|)
  Chunk rho_;
  Chunk weight_;
};

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

// The default settings of the adaptive kernel (NlsOptions): the table every solver with them shares.
constexpr double kDefaultTruncation = 10.0;
constexpr double kDefaultAlphaMin = -10.0;

// The table of the default settings, built on the first call (~40 ms; thread-safe) and shared
// read-only from then on: a constant of the process, not state (the same values whoever asks
// first). Solvers with the default settings use it unless given a table; a navigation stack that
// calls it at start-up keeps the build out of its first range callback.
std::shared_ptr<const LogPartitionTable> DefaultLogPartitionTable();
// The table of (truncation, alpha_min): the default settings' shared one, or a new one (~40 ms).
std::shared_ptr<const LogPartitionTable> MakeLogPartitionTable(double truncation, double alpha_min);

// Tables by (truncation, alpha_min), each built on first request (~40 ms; the default settings'
// is DefaultLogPartitionTable()) and then shared by every solver that asks. Owned by whoever builds the solvers (the registry's Components, or your code):
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
// The residuals are summarized in kBins bins of |x|: [0, 2^-6), then four per octave up to 2^10
// (the exponent and the two leading mantissa bits of |x|: no log needed), and beyond. Each bin
// keeps its count and the mean of x^2, so one NLL evaluation costs one kernel evaluation per
// occupied bin instead of N. The truncation only normalizes the density; residuals beyond it
// still count with their rho.
class AlphaSelector {
 public:
  static constexpr int kBins = 66;                 // [0, 2^-6), 64 quarter octaves, [2^10, inf)
  static_assert(kBins <= kChunk, "the occupied bins are one chunk");
  static constexpr double kAlphaTolerance = 1e-2;  // the search's tolerance on alpha

  explicit AlphaSelector(std::shared_ptr<const LogPartitionTable> table);

  void Clear();
  void Add(double x);            // one normalized residual r / c
  void AddAll(const Chunk& x);   // many at once
  // argmin NLL over [alpha_min, 2]: a coarse grid, then Brent's method around the best grid point;
  // or, given the previous iteration's alpha, Brent's method around it. Not const: it evaluates
  // the NLL (below).
  double Select(std::optional<double> previous_alpha = std::nullopt);
  // From the histogram: what Select minimizes. Not const: it summarizes the bins on first use
  // after a change (their root-mean-square residuals) and evaluates the kernel on them at once.
  double Nll(double alpha);
  // NLL evaluated exactly on residuals, for tests.
  static double ExactNll(std::span<const double> x, double alpha, const LogPartitionTable& table);
  static int BinOf(double x);  // the bin of a normalized residual

 private:
  void Summarize();  // occupied_count_ and occupied_x_rms_ from the bins

  std::shared_ptr<const LogPartitionTable> table_;
  std::array<double, kBins> bin_count_{};
  std::array<double, kBins> bin_sum_x_squared_{};
  double total_count_ = 0.0;
  bool summarized_ = false;
  Chunk occupied_count_;  // the bins that hold residuals: their counts...
  Chunk occupied_x_rms_;  // ...and the root mean square of their residuals
  KernelArrays kernel_;
};

}  // namespace anchorbench::estimator
