// Every registered solver, on the same three cases (issue: "a conformance test over every
// registered solver"). A new solver registered in RegisterBuiltinSolvers is picked up here.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>
#include <nlopt.hpp>

#include "anchorbench/estimator/nlopt_solver.hpp"
#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/testing/test_data.hpp"
#include "builtins.hpp"

namespace anchorbench::registry {
namespace {

using namespace estimator;  // the solvers under test

// RANSAC is a filter stage, not a registered solver; it wraps one, and must conform like one.
constexpr const char* kRansacAroundLmL2 = "ransac(lm_l2)";
constexpr const char* kFullSolveRansacAroundLmL2 = "ransac_full_solve(lm_l2)";

std::vector<std::string> SolverNames() {
  std::vector<std::string> names;
  for (const auto& [name, description] : testing::Builtins().solvers.List()) {
    if (name.back() != '>') names.push_back(name);  // prefix entries are tested through examples below
  }
  for (const char* algorithm : {"LN_BOBYQA", "LN_NELDERMEAD", "LN_SBPLX", "LD_LBFGS"}) {
    names.push_back(std::string("nlopt:") + algorithm);
  }
  names.push_back(kRansacAroundLmL2);
  names.push_back(kFullSolveRansacAroundLmL2);
  return names;
}

std::unique_ptr<Solver> Make(const std::string& name) {
  if (name == kRansacAroundLmL2) return std::make_unique<RansacSolver>(Make("lm_l2"), RansacOptions{}, 42);
  if (name == kFullSolveRansacAroundLmL2) {
    RansacOptions options;
    options.scheme = RansacScheme::kFullSolve;
    return std::make_unique<RansacSolver>(Make("lm_l2"), options, 42);
  }
  AnchorSolverOptions options;
  options.nls.kernel_scale_m = 0.1;
  std::string why;
  auto solver = testing::Builtins().solvers.Create(name, {options, 42, testing::Builtins().tables.get()}, &why);
  EXPECT_TRUE(solver) << why;
  return solver;
}

class SolverConformance : public ::testing::TestWithParam<std::string> {};

TEST_P(SolverConformance, NoiseFreeWellConditionedDataGivesTheAnchorTo1e6) {
  const auto solver = Make(GetParam());
  for (int trial = 0; trial < 5; ++trial) {
    auto rng = anchorbench::testing::TestStream(500 + trial);
    const Eigen::Vector3d p_anchor = anchorbench::testing::UniformIn(rng, Eigen::Vector3d(-10, -10, 0), Eigen::Vector3d(10, 10, 5));
    const auto data = anchorbench::testing::BoxData(rng, 150, p_anchor, p_anchor + Eigen::Vector3d(4, 3, -1), 5.0, 0.25, 0.0);
    const SolveResult result = solver->Solve(data.p_world_tag, data.range_m);
    ASSERT_TRUE(Succeeded(result.status)) << ToString(result.status);
    EXPECT_LT((result.p_world_anchor - p_anchor).norm(), 1e-6) << "trial " << trial;
    EXPECT_NEAR(result.bias_m, 0.25, 1e-6);
  }
}

TEST_P(SolverConformance, CollinearPositionsGiveAFailureStatusNoNanNoException) {
  const auto solver = Make(GetParam());
  std::vector<Eigen::Vector3d> p;
  std::vector<double> d;
  for (int k = 0; k < 100; ++k) {
    p.emplace_back(0.2 * k, 1.0, 1.5);
    d.push_back((p.back() - Eigen::Vector3d(8, 4, 3)).norm() + 0.1);
  }
  SolveResult result;
  EXPECT_NO_THROW(result = solver->Solve(p, d));
  EXPECT_FALSE(Succeeded(result.status)) << ToString(result.status);
  EXPECT_TRUE(result.p_world_anchor.allFinite());
  EXPECT_TRUE(std::isfinite(result.bias_m));
}

TEST_P(SolverConformance, TwentyPercentOutliersGiveABoundedError) {
  const auto solver = Make(GetParam());
  double worst_m = 0.0;
  for (int trial = 0; trial < 5; ++trial) {
    auto rng = anchorbench::testing::TestStream(600 + trial);
    const Eigen::Vector3d p_anchor(0, 0, 3);
    auto data = anchorbench::testing::BoxData(rng, 300, p_anchor, Eigen::Vector3d(5, 1, 1), 5.0, 0.1, 0.1);
    for (double& d : data.range_m)
      if (rng.Uniform() < 0.2) d += rng.Uniform(1.0, 5.0);
    const SolveResult result = solver->Solve(data.p_world_tag, data.range_m);
    ASSERT_TRUE(result.p_world_anchor.allFinite());
    if (Succeeded(result.status)) worst_m = std::max(worst_m, (result.p_world_anchor - p_anchor).norm());
  }
  // Bounded, not accurate: plain least squares is not robust; the bound is the outliers' scale.
  EXPECT_LT(worst_m, 5.0);
}

INSTANTIATE_TEST_SUITE_P(AllRegistered, SolverConformance, ::testing::ValuesIn(SolverNames()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// RANSAC's iteration count: n = log(1 - p) / log(1 - (1 - e)^s); the paper's p = 0.95, s = 60,
// e = 0.1 give 1666 (its printed formula omits the log in the denominator, its number does not).
TEST(Ransac, IterationsOfThePapersTableII) {
  RansacOptions options;
  options.scheme = RansacScheme::kFullSolve;
  options.success_probability = 0.95;
  options.subset_size = 60;
  EXPECT_EQ(options.Iterations(), 1666);
}

// The adaptive count: log(1 - p) / log(1 - w^s), at least one draw, at most the cap.
TEST(Ransac, AdaptiveDrawsFollowTheInlierShare) {
  EXPECT_EQ(AdaptiveDraws(1.0, 6, 0.99, 2000), 1);
  EXPECT_EQ(AdaptiveDraws(0.9, 6, 0.99, 2000), 7);    // 0.9^6 = 0.531: log(0.01) / log(0.469) = 6.09
  EXPECT_EQ(AdaptiveDraws(0.5, 6, 0.99, 2000), 293);  // 0.5^6 = 1/64: log(0.01) / log(63/64) = 292.4
  EXPECT_EQ(AdaptiveDraws(0.0, 6, 0.99, 2000), 2000);
  EXPECT_EQ(AdaptiveDraws(0.01, 6, 0.99, 2000), 2000);
}

TEST(SolverRegistry, UnknownNamesAreRefusedWithAReason) {
  SolverRegistry registry("solver");
  RegisterBuiltinSolvers(registry);
  std::string why;
  EXPECT_EQ(registry.Create("lm_magic", {}, &why), nullptr);
  EXPECT_NE(why.find("unknown solver 'lm_magic'"), std::string::npos) << why;
  EXPECT_EQ(registry.Create("nlopt:LN_NOPE", {}, &why), nullptr);
  EXPECT_NE(why.find("solver 'nlopt:LN_NOPE': 'LN_NOPE' is not an NLopt algorithm"), std::string::npos) << why;
  EXPECT_FALSE(registry.Knows("nlopt:GN_CRS2_LM", &why));
  EXPECT_NE(why.find("draws from NLopt's process-wide random generator"), std::string::npos) << why;
  EXPECT_TRUE(registry.Knows("nlopt:LN_BOBYQA"));
  EXPECT_TRUE(registry.Knows("lm_l2"));
  EXPECT_FALSE(registry.Knows("lm_magic"));
}

// The list of stochastic NLopt algorithms the solver refuses, checked against NLopt itself: every
// algorithm it accepts must evaluate the same points whatever NLopt's generator was seeded with.
// (The test seeds NLopt's process-wide generator; the library never does.)
TEST(NloptSolver, EveryAcceptedAlgorithmIsDeterministic) {
  static std::uint64_t hash = 0;
  auto objective = [](unsigned n, const double* x, double* gradient, void*) {
    double value = 0.0;
    for (unsigned i = 0; i < n; ++i) {
      std::uint64_t bits;
      std::memcpy(&bits, &x[i], sizeof bits);
      hash = hash * 1099511628211ull ^ bits;
      const double d = x[i] - 0.3 * i;
      value += d * d + 0.1 * std::sin(5.0 * x[i]);
      if (gradient) gradient[i] = 2.0 * d + 0.5 * std::cos(5.0 * x[i]);
    }
    return value;
  };
  int accepted = 0;
  for (int a = 0; a < NLOPT_NUM_ALGORITHMS; ++a) {
    std::uint64_t evaluated[2];
    for (unsigned long seed : {1ul, 2ul}) {
      hash = 1469598103934665603ull;
      try {
        nlopt::opt optimizer(static_cast<nlopt::algorithm>(a), 4);
        nlopt::opt local(nlopt::LN_BOBYQA, 4);
        local.set_xtol_rel(1e-8);
        optimizer.set_local_optimizer(local);
        optimizer.set_lower_bounds(-5.0);
        optimizer.set_upper_bounds(5.0);
        optimizer.set_min_objective(objective, nullptr);
        optimizer.set_maxeval(3000);
        optimizer.set_xtol_rel(1e-10);
        nlopt::srand(seed);
        std::vector<double> x(4, 1.0);
        double value = 0.0;
        optimizer.optimize(x, value);
      } catch (const std::exception&) {
        // an algorithm this build lacks, or one that gave up: the points it evaluated still count
      }
      evaluated[seed - 1] = hash;
    }
    const bool deterministic = evaluated[0] == evaluated[1];
    if (!NloptSolver::IsStochastic(a)) {
      ++accepted;
      EXPECT_TRUE(deterministic) << nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(a))
                                 << " is accepted but its evaluations depend on NLopt's seed";
    }
  }
  EXPECT_GT(accepted, 20);
}

}  // namespace
}  // namespace anchorbench::registry
