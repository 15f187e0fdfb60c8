#include "anchorbench/estimator/robust_kernel.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <mutex>
#include <utility>


namespace anchorbench::estimator {
namespace {

constexpr double kLimitTolerance = 1e-9;  // |alpha - 2| or |alpha| below this: use the exact limit
// log Z~ is tabulated every 0.01 in alpha and interpolated linearly: the alpha search stops at a
// tolerance of 0.01 (AlphaSelector::kAlphaTolerance), so a finer table would not change a choice.
constexpr double kTableAlphaStep = 0.01;
constexpr int kSimpsonIntervals = 1000;  // over [0, truncation]; the integrand is smooth

// The alpha search (ours; the paper does not say how alpha is minimized). From scratch, a grid of
// kCoarseGridPoints over [alpha_min, 2] (every 1 at the default alpha_min = -10) guards against
// the NLL's shallow second minimum; Brent's method then refines within a grid cell of the best
// grid point (or of the previous iteration's alpha) to kAlphaTolerance, in ~8 evaluations.
constexpr int kCoarseGridPoints = 13;
constexpr int kMaxRefineEvaluations = 40;

// Brent's method for a minimum of f on [a, b] (Brent 1973, "Algorithms for Minimization without
// Derivatives", ch. 5, procedure localmin): golden-section steps, and parabolic steps through
// the best three points where they stay safely inside. Returns (x, f(x)) of the best point.
template <typename F>
std::pair<double, double> BrentMinimum(F f, double a, double b, double tolerance, int max_evaluations) {
  constexpr double kGolden = 0.3819660112501051;  // (3 - sqrt(5)) / 2
  const double sqrt_epsilon = std::sqrt(std::numeric_limits<double>::epsilon());
  double x = a + kGolden * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  double d = 0.0, e = 0.0;
  for (int evaluations = 1; evaluations < max_evaluations; ++evaluations) {
    const double middle = 0.5 * (a + b);
    const double tol1 = sqrt_epsilon * std::abs(x) + tolerance / 3.0;
    const double tol2 = 2.0 * tol1;
    if (std::abs(x - middle) <= tol2 - 0.5 * (b - a)) break;
    double p = 0.0, q = 0.0, r = 0.0;
    if (std::abs(e) > tol1) {  // a parabola through x, w, v
      r = (x - w) * (fx - fv);
      q = (x - v) * (fx - fw);
      p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      r = e;
      e = d;
    }
    if (std::abs(p) < std::abs(0.5 * q * r) && p > q * (a - x) && p < q * (b - x)) {
      d = p / q;  // the parabola's minimum, inside and moving less than half the step before last
      const double u = x + d;
      if (u - a < tol2 || b - u < tol2) d = x < middle ? tol1 : -tol1;
    } else {
      e = x < middle ? b - x : a - x;  // golden section into the larger part
      d = kGolden * e;
    }
    const double u = std::abs(d) >= tol1 ? x + d : (d > 0.0 ? x + tol1 : x - tol1);
    const double fu = f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return {x, fx};
}

bool IsL2(double alpha) { return std::abs(alpha - 2.0) < kLimitTolerance; }
bool IsCauchy(double alpha) { return std::abs(alpha) < kLimitTolerance; }

}  // namespace

KernelValue EvaluateKernel(double x, double alpha) {
  const double x2 = x * x;
  if (IsL2(alpha)) return {0.5 * x2, 1.0};
  const double abs_alpha_minus_2 = std::abs(alpha - 2.0);
  const double u = x2 / abs_alpha_minus_2;  // base = u + 1 = x^2/|alpha-2| + 1
  // log1p only where it earns its cost (glibc's log1p is several times slower than log): for
  // u >= 1e-3, log(1 + u) is within ~1e-13 relative.
  const double log_base = u < 1e-3 ? std::log1p(u) : std::log(1.0 + u);
  if (IsCauchy(alpha)) return {log_base, 1.0 / (1.0 + u)};  // |alpha-2| = 2: log(x^2/2 + 1), 2/(x^2+2)
  // One power serves both: weight = base^(alpha/2 - 1), base^(alpha/2) = weight * base.
  const double weight = std::exp((0.5 * alpha - 1.0) * log_base);
  const double power_minus_1 = 0.5 * alpha * log_base < 1e-3 && 0.5 * alpha * log_base > -1e-3
                                   ? std::expm1(0.5 * alpha * log_base)  // keep precision near alpha = 0
                                   : weight * (1.0 + u) - 1.0;
  return {abs_alpha_minus_2 / alpha * power_minus_1, weight};  // Eq. (13)
}

void KernelArrays::Evaluate(const Chunk& x, double alpha) {
  if (IsL2(alpha)) {
    rho_ = 0.5 * x.square();
    weight_.setOnes(x.size());
    return;
  }
  const double abs_alpha_minus_2 = std::abs(alpha - 2.0);
  u_ = x.square() / abs_alpha_minus_2;
  base_ = u_ + 1.0;
  // log1p(u) to full precision without a scalar call: log(1 + u) minus what rounding 1 + u added,
  // (1 + u) - 1 - u, to first order (Goldberg's correction; it matters only where 1 + u is near 1,
  // so the division by 1 + u of the exact form is left out).
  log_base_ = base_.log() - ((base_ - 1.0) - u_);
  if (IsCauchy(alpha)) {
    rho_ = log_base_;
    weight_ = base_.inverse();
    return;
  }
  weight_ = ((0.5 * alpha - 1.0) * log_base_).exp();  // one power serves both, as in the scalar form
  // base^(alpha/2) - 1 cancels near alpha = 0: there expm1's series (its next term is t^6/720,
  // below 2e-21 of it for |t| < 1e-3), elsewhere weight * base - 1. Both, then a select: no branch.
  const auto t = (0.5 * alpha) * log_base_;
  const auto series = t * (1.0 + t * (0.5 + t * (1.0 / 6.0 + t * (1.0 / 24.0 + t / 120.0))));
  rho_ = (abs_alpha_minus_2 / alpha) * (t.abs() < 1e-3).select(series, weight_ * base_ - 1.0);  // Eq. (13)
}

double Rho(double x, double alpha) { return EvaluateKernel(x, alpha).rho; }
double Weight(double x, double alpha) { return EvaluateKernel(x, alpha).weight; }

double LogPartitionTable::IntegrateZ(double alpha, double truncation) {
  // Composite Simpson on [0, T], doubled by symmetry.
  const double h = truncation / kSimpsonIntervals;
  double sum = std::exp(-Rho(0.0, alpha)) + std::exp(-Rho(truncation, alpha));
  for (int i = 1; i < kSimpsonIntervals; ++i) {
    sum += (i % 2 == 1 ? 4.0 : 2.0) * std::exp(-Rho(i * h, alpha));
  }
  return 2.0 * sum * h / 3.0;
}

LogPartitionTable::LogPartitionTable(double truncation, double alpha_min)
    : truncation_(truncation), alpha_min_(alpha_min) {
  const int intervals = std::max(1, static_cast<int>(std::ceil((2.0 - alpha_min) / kTableAlphaStep)));
  alpha_step_ = (2.0 - alpha_min) / intervals;
  log_z_.resize(intervals + 1);
  for (int i = 0; i <= intervals; ++i) {
    const double alpha = i == intervals ? 2.0 : alpha_min + i * alpha_step_;
    log_z_[i] = std::log(IntegrateZ(alpha, truncation));
  }
}

std::shared_ptr<const LogPartitionTable> DefaultLogPartitionTable() {
  static const std::shared_ptr<const LogPartitionTable> table =
      std::make_shared<const LogPartitionTable>(kDefaultTruncation, kDefaultAlphaMin);
  return table;
}

std::shared_ptr<const LogPartitionTable> MakeLogPartitionTable(double truncation, double alpha_min) {
  if (truncation == kDefaultTruncation && alpha_min == kDefaultAlphaMin) return DefaultLogPartitionTable();
  return std::make_shared<const LogPartitionTable>(truncation, alpha_min);
}

std::shared_ptr<const LogPartitionTable> LogPartitionTables::Get(double truncation, double alpha_min) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& table : tables_) {
    if (table->truncation() == truncation && table->alpha_min() == alpha_min) return table;
  }
  tables_.push_back(MakeLogPartitionTable(truncation, alpha_min));
  return tables_.back();
}

double LogPartitionTable::LogZ(double alpha) const {
  const double position = std::clamp((alpha - alpha_min_) / alpha_step_, 0.0,
                                     static_cast<double>(log_z_.size() - 1));
  const std::size_t i = std::min(static_cast<std::size_t>(position), log_z_.size() - 2);
  const double fraction = position - static_cast<double>(i);
  return log_z_[i] + fraction * (log_z_[i + 1] - log_z_[i]);
}

AlphaSelector::AlphaSelector(std::shared_ptr<const LogPartitionTable> table) : table_(std::move(table)) {}

void AlphaSelector::Clear() {
  bin_count_.fill(0.0);
  bin_sum_x_squared_.fill(0.0);
  total_count_ = 0.0;
  summarized_ = false;
}

int AlphaSelector::BinOf(double x) {
  // The biased exponent and the two leading mantissa bits of |x|: four bins per octave. 2^-6 has
  // exponent 1023 - 6; everything below it shares bin 0; 2^10 and beyond (infinity and NaN too)
  // the last bin.
  constexpr int kFirstCode = (1023 - 6) << 2;
  const int code = static_cast<int>(std::bit_cast<std::uint64_t>(std::abs(x)) >> 50);
  return std::clamp(code - kFirstCode + 1, 0, kBins - 1);
}

void AlphaSelector::Add(double x) {
  const auto bin = static_cast<std::size_t>(BinOf(x));
  bin_count_[bin] += 1.0;
  bin_sum_x_squared_[bin] += x * x;
  total_count_ += 1.0;
  summarized_ = false;
}

void AlphaSelector::AddAll(const Chunk& x) {
  for (Eigen::Index k = 0; k < x.size(); ++k) Add(x[k]);
}

void AlphaSelector::Summarize() {
  int occupied = 0;
  for (double count : bin_count_) occupied += count > 0.0;
  occupied_count_.resize(occupied);
  occupied_x_rms_.resize(occupied);
  for (int b = 0, i = 0; b < kBins; ++b) {
    if (bin_count_[b] == 0.0) continue;
    occupied_count_[i] = bin_count_[b];
    occupied_x_rms_[i] = std::sqrt(bin_sum_x_squared_[b] / bin_count_[b]);
    ++i;
  }
  summarized_ = true;
}

double AlphaSelector::Nll(double alpha) {
  if (!summarized_) Summarize();
  kernel_.Evaluate(occupied_x_rms_, alpha);
  return total_count_ * table_->LogZ(alpha) + (occupied_count_ * kernel_.rho()).sum();
}

double AlphaSelector::ExactNll(std::span<const double> x, double alpha, const LogPartitionTable& table) {
  double sum_rho = 0.0;
  for (double xi : x) sum_rho += Rho(xi, alpha);
  return static_cast<double>(x.size()) * table.LogZ(alpha) + sum_rho;
}

double AlphaSelector::Select(std::optional<double> previous_alpha) {
  const double alpha_min = table_->alpha_min();
  if (total_count_ == 0.0) return 2.0;
  const double grid_step = (2.0 - alpha_min) / (kCoarseGridPoints - 1);
  double best_alpha = previous_alpha.value_or(2.0);
  double best_nll = Nll(best_alpha);
  if (!previous_alpha) {
    // From scratch, a coarse grid first: the NLL can have a shallow second minimum that a local
    // search from a fixed start would miss.
    for (int i = 0; i < kCoarseGridPoints - 1; ++i) {
      const double alpha = alpha_min + i * grid_step;
      const double nll = Nll(alpha);
      if (nll < best_nll) {
        best_nll = nll;
        best_alpha = alpha;
      }
    }
  }
  // From the grid: within its cell either side. From the previous alpha: within a quarter cell
  // either side (alpha moves little from one iteration to the next; if it moves more, the next
  // iteration continues from the edge).
  const double reach = previous_alpha ? 0.25 * grid_step : grid_step;
  const double lower = std::max(alpha_min, best_alpha - reach);
  const double upper = std::min(2.0, best_alpha + reach);
  const auto [alpha, nll] =
      BrentMinimum([this](double a) { return Nll(a); }, lower, upper, kAlphaTolerance, kMaxRefineEvaluations);
  return nll <= best_nll ? alpha : best_alpha;
}

}  // namespace anchorbench::estimator
