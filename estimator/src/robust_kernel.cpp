#include "anchorbench/estimator/robust_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <utility>

#include <nlopt.hpp>

namespace anchorbench::estimator {
namespace {

constexpr double kLimitTolerance = 1e-9;  // |alpha - 2| or |alpha| below this: use the exact limit
// log Z~ is tabulated every 0.01 in alpha and interpolated linearly: the alpha search stops at a
// tolerance of 0.01 (AlphaSelector::kAlphaTolerance), so a finer table would not change a choice.
constexpr double kTableAlphaStep = 0.01;
constexpr int kSimpsonIntervals = 1000;  // over [0, truncation]; the integrand is smooth

// The alpha search (ours; the paper does not say how alpha is minimized). From scratch, a grid of
// kCoarseGridPoints over [alpha_min, 2] (every 1 at the default alpha_min = -10) guards against
// the NLL's shallow second minimum; COBYLA then refines around the best grid point (or the
// previous iteration's alpha) with a first step of a quarter grid cell, within
// kMaxRefineEvaluations evaluations: it needs ~15 to reach the 0.01 tolerance from there.
constexpr int kCoarseGridPoints = 13;
constexpr double kFirstStepInGridCells = 0.25;
constexpr int kMaxRefineEvaluations = 40;

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

std::shared_ptr<const LogPartitionTable> LogPartitionTables::Get(double truncation, double alpha_min) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& table : tables_) {
    if (table->truncation() == truncation && table->alpha_min() == alpha_min) return table;
  }
  tables_.push_back(std::make_shared<const LogPartitionTable>(truncation, alpha_min));
  return tables_.back();
}

double LogPartitionTable::LogZ(double alpha) const {
  const double position = std::clamp((alpha - alpha_min_) / alpha_step_, 0.0,
                                     static_cast<double>(log_z_.size() - 1));
  const std::size_t i = std::min(static_cast<std::size_t>(position), log_z_.size() - 2);
  const double fraction = position - static_cast<double>(i);
  return log_z_[i] + fraction * (log_z_[i + 1] - log_z_[i]);
}

AlphaSelector::AlphaSelector(std::shared_ptr<const LogPartitionTable> table)
    : table_(std::move(table)), optimizer_(std::make_unique<nlopt::opt>(nlopt::LN_COBYLA, 1)) {
  auto objective = [](unsigned, const double* a, double*, void* self) {
    return static_cast<const AlphaSelector*>(self)->Nll(a[0]);
  };
  optimizer_->set_min_objective(objective, this);
  optimizer_->set_xtol_abs(kAlphaTolerance);
  optimizer_->set_maxeval(kMaxRefineEvaluations);
}

AlphaSelector::~AlphaSelector() = default;

void AlphaSelector::Clear() {
  bin_count_.fill(0.0);
  bin_sum_x_squared_.fill(0.0);
  total_count_ = 0.0;
}

// Upper edges of the histogram bins in |x|: even in log(1 + |x|) up to kMaxAbsX. Computed once,
// immutable (a constant table, not state).
static const std::array<double, AlphaSelector::kBins - 1>& BinEdges() {
  static const auto edges = [] {
    std::array<double, AlphaSelector::kBins - 1> e{};
    for (int b = 0; b < AlphaSelector::kBins - 1; ++b) {
      e[b] = std::expm1((b + 1) * std::log1p(AlphaSelector::kMaxAbsX) / AlphaSelector::kBins);
    }
    return e;
  }();
  return edges;
}

void AlphaSelector::Add(double x) {
  const double abs_x = std::abs(x);
  const auto& edges = BinEdges();
  // A binary search over the edges costs less than the log1p it replaces.
  const auto bin = static_cast<int>(std::upper_bound(edges.begin(), edges.end(), abs_x) - edges.begin());
  bin_count_[bin] += 1.0;
  bin_sum_x_squared_[bin] += abs_x * abs_x;
  total_count_ += 1.0;
}

double AlphaSelector::Nll(double alpha) const {
  double sum_rho = 0.0;
  for (int b = 0; b < kBins; ++b) {
    if (bin_count_[b] == 0.0) continue;
    const double x_rms = std::sqrt(bin_sum_x_squared_[b] / bin_count_[b]);
    sum_rho += bin_count_[b] * Rho(x_rms, alpha);
  }
  return total_count_ * table_->LogZ(alpha) + sum_rho;
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
  double best_alpha = 2.0;
  double best_nll = Nll(2.0);
  double lower = alpha_min, upper = 2.0;
  if (previous_alpha) {
    // Inside the alternation alpha moves little between iterations: refine locally from the last one.
    best_alpha = *previous_alpha;
    best_nll = Nll(best_alpha);
  } else {
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
    lower = std::max(alpha_min, best_alpha - grid_step);
    upper = std::min(2.0, best_alpha + grid_step);
  }
  nlopt::opt& optimizer = *optimizer_;
  optimizer.set_lower_bounds(lower);
  optimizer.set_upper_bounds(upper);
  optimizer.set_initial_step(kFirstStepInGridCells * grid_step);
  std::vector<double> alpha{best_alpha};
  double nll = best_nll;
  try {
    optimizer.optimize(alpha, nll);
  } catch (const std::exception&) {
    return best_alpha;  // NLopt gave up (round-off): the best point so far stands
  }
  return nll <= best_nll ? alpha[0] : best_alpha;
}

}  // namespace anchorbench::estimator
