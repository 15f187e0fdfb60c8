#include "anchorbench/estimator/robust_kernel.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "anchorbench/estimator/nls_solver.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

const double kAlphas[] = {2.0, 1.9999, 1.0, 0.5, 1e-7, 0.0, -1e-7, -2.0, -5.0, -10.0};

TEST(RobustKernel, DerivativeIsXTimesWeightByFiniteDifferences) {
  for (double alpha : kAlphas) {
    for (double x : {0.0, 0.1, 0.7, 1.0, 2.5, 6.0, 30.0}) {
      const double h = 1e-5 * std::max(1.0, x);
      const double numeric = (Rho(x + h, alpha) - Rho(x - h, alpha)) / (2.0 * h);
      EXPECT_NEAR(numeric, x * Weight(x, alpha), 1e-6 * std::max(1.0, std::abs(numeric)))
          << "alpha " << alpha << " x " << x;
    }
  }
}

TEST(RobustKernel, ClosedFormsAtTwoZeroMinusTwo) {
  for (double x : {0.0, 0.3, 1.0, 4.0, 20.0}) {
    const double x2 = x * x;
    EXPECT_DOUBLE_EQ(Rho(x, 2.0), 0.5 * x2);  // L2
    EXPECT_DOUBLE_EQ(Weight(x, 2.0), 1.0);
    EXPECT_NEAR(Rho(x, 0.0), std::log(0.5 * x2 + 1.0), 1e-15);  // Cauchy
    EXPECT_NEAR(Weight(x, 0.0), 2.0 / (x2 + 2.0), 1e-15);
    // alpha = -2 (Geman-McClure): rho = 2x^2/(x^2+4), w = 16/(x^2+4)^2.
    EXPECT_NEAR(Rho(x, -2.0), 2.0 * x2 / (x2 + 4.0), 1e-14);
    EXPECT_NEAR(Weight(x, -2.0), 16.0 / ((x2 + 4.0) * (x2 + 4.0)), 1e-14);
  }
}

TEST(RobustKernel, GeneralFormApproachesTheExactLimits) {
  for (double x : {0.5, 2.0, 8.0}) {
    EXPECT_NEAR(Rho(x, 2.0 - 1e-6), Rho(x, 2.0), 1e-4 * Rho(x, 2.0));
    EXPECT_NEAR(Rho(x, 1e-8), Rho(x, 0.0), 1e-7);
    EXPECT_NEAR(Rho(x, -1e-8), Rho(x, 0.0), 1e-7);
  }
}

// Reference values of Z~ (design notes): truncation 10 | 50 | exact.
TEST(LogPartitionTable, IntegralMatchesReferenceValues) {
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(2.0, 10.0), std::sqrt(2.0 * std::numbers::pi), 1e-6);
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(1.0, 10.0), 3.2721, 1e-4);
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(1.0, 50.0), 3.2723, 1e-4);
  // alpha = 0: 2 sqrt(2) atan(T / sqrt(2)), tending to pi sqrt(2).
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(0.0, 10.0), 2.0 * std::sqrt(2.0) * std::atan(10.0 / std::sqrt(2.0)), 1e-7);
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(0.0, 10.0), 4.0455, 1e-4);
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(0.0, 50.0), 4.3629, 1e-4);
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(-2.0, 10.0), 5.730, 1e-3);
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(-2.0, 50.0), 16.730, 1e-3);
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(-10.0, 10.0), 7.724, 1e-3);
  EXPECT_NEAR(LogPartitionTable::IntegrateZ(-10.0, 50.0), 31.820, 1e-3);
}

TEST(LogPartitionTable, InterpolationMatchesDirectIntegralOffGrid) {
  LogPartitionTables tables;
  const auto table = tables.Get(10.0, -10.0);
  EXPECT_EQ(table, tables.Get(10.0, -10.0));  // built once, shared by whoever asks the same owner
  EXPECT_NE(table, tables.Get(50.0, -10.0));
  for (double alpha : {1.99, 1.234, 0.005, -0.777, -3.3333, -9.995}) {
    EXPECT_NEAR(table->LogZ(alpha), std::log(LogPartitionTable::IntegrateZ(alpha, 10.0)), 2e-5) << alpha;
  }
}

// Solvers with the default settings share one table without being handed it; other settings
// build their own, and a table handed over for other settings is not used.
TEST(LogPartitionTable, TheDefaultSettingsShareOneTable) {
  const auto shared = DefaultLogPartitionTable();
  EXPECT_EQ(shared, DefaultLogPartitionTable());
  EXPECT_EQ(LogPartitionTables().Get(kDefaultTruncation, kDefaultAlphaMin), shared);
  EXPECT_EQ(NlsSolver().table(), shared);
  EXPECT_EQ(NlsSolver(NlsOptions{}, std::make_shared<const LogPartitionTable>(50.0, -10.0)).table(), shared);
  NlsOptions other;
  other.truncation = 20.0;
  const NlsSolver own(other);
  ASSERT_NE(own.table(), nullptr);
  EXPECT_NE(own.table(), shared);
  EXPECT_EQ(own.table()->truncation(), 20.0);
  other.kernel = KernelMode::kL2;
  EXPECT_EQ(NlsSolver(other).table(), nullptr);
}

std::vector<double> GaussianWithOutliers(int n, double outlier_fraction, std::uint64_t seed) {
  auto rng = testing::TestStream(seed);
  std::vector<double> x;
  for (int i = 0; i < n; ++i) {
    x.push_back(rng.Uniform() < outlier_fraction ? rng.Uniform(5.0, 50.0) : rng.Normal());
  }
  return x;
}

TEST(AlphaSelector, HistogramNllTracksExactNll) {
  const auto table = std::make_shared<const LogPartitionTable>(10.0, -10.0);
  const auto x = GaussianWithOutliers(2000, 0.1, 3);
  AlphaSelector selector(table);
  for (double xi : x) selector.Add(xi);
  for (double alpha : {2.0, 1.0, 0.0, -2.0, -10.0}) {
    const double exact = AlphaSelector::ExactNll(x, alpha, *table);
    EXPECT_NEAR(selector.Nll(alpha), exact, 0.01 * std::abs(exact)) << alpha;
  }
}

TEST(AlphaSelector, GaussianResidualsKeepAlphaNearTwoOutliersPushItNegative) {
  const auto table = std::make_shared<const LogPartitionTable>(10.0, -10.0);
  AlphaSelector clean(table);
  for (double xi : GaussianWithOutliers(3000, 0.0, 5)) clean.Add(xi);
  EXPECT_GT(clean.Select(), 1.5);  // the Gaussian is the alpha = 2 member of the family

  AlphaSelector dirty(table);
  const auto x = GaussianWithOutliers(3000, 0.2, 6);
  for (double xi : x) dirty.Add(xi);
  const double alpha = dirty.Select();
  EXPECT_LT(alpha, 0.0);
  // The choice is the minimum of the exact NLL too, within the grid/histogram resolution.
  for (double other : {2.0, 1.0, 0.0, -2.0, -6.0, -10.0}) {
    EXPECT_LE(AlphaSelector::ExactNll(x, alpha, *table), AlphaSelector::ExactNll(x, other, *table) + 1.0);
  }
}

}  // namespace
}  // namespace anchorbench::estimator
