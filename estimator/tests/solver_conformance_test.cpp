// Every registered solver, on the same three cases (issue: "a conformance test over every
// registered solver"). A new solver registered in RegisterBuiltinSolvers is picked up here.
#include <cmath>

#include <gtest/gtest.h>

#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/estimator/solver_registry.hpp"
#include "test_data.hpp"

namespace anchorbench::estimator {
namespace {

// RANSAC is a filter stage, not a registered solver; it wraps one, and must conform like one.
constexpr const char* kRansacAroundLmL2 = "ransac(lm_l2)";

std::vector<std::string> SolverNames() {
  std::vector<std::string> names;
  for (const auto& [name, description] : testing::Builtins().solvers.List()) {
    if (name.back() != '>') names.push_back(name);  // prefix entries are tested through examples below
  }
  for (const char* algorithm : {"LN_BOBYQA", "LN_NELDERMEAD", "LN_SBPLX", "LD_LBFGS"}) {
    names.push_back(std::string("nlopt:") + algorithm);
  }
  names.push_back(kRansacAroundLmL2);
  return names;
}

std::unique_ptr<Solver> Make(const std::string& name) {
  if (name == kRansacAroundLmL2) return std::make_unique<RansacSolver>(RansacOptions{}, Make("lm_l2"), 42);
  AnchorSolverOptions options;
  options.nls.kernel_scale_m = 0.1;
  std::string why;
  auto solver = testing::Builtins().solvers.Create(name, {options, 42}, &why);
  EXPECT_TRUE(solver) << why;
  return solver;
}

class SolverConformance : public ::testing::TestWithParam<std::string> {};

TEST_P(SolverConformance, NoiseFreeWellConditionedDataGivesTheAnchorTo1e6) {
  const auto solver = Make(GetParam());
  for (int trial = 0; trial < 5; ++trial) {
    auto rng = testing::TestStream(500 + trial);
    const Eigen::Vector3d p_anchor(rng.Uniform(-10, 10), rng.Uniform(-10, 10), rng.Uniform(0, 5));
    const auto data = testing::BoxData(rng, 150, p_anchor, p_anchor + Eigen::Vector3d(4, 3, -1), 5.0, 0.25, 0.0);
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
    auto rng = testing::TestStream(600 + trial);
    const Eigen::Vector3d p_anchor(0, 0, 3);
    auto data = testing::BoxData(rng, 300, p_anchor, Eigen::Vector3d(5, 1, 1), 5.0, 0.1, 0.1);
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
  EXPECT_EQ(options.Iterations(), 1666);
}

TEST(SolverRegistry, UnknownNamesAreRefusedWithAReason) {
  SolverRegistry registry("solver");
  RegisterBuiltinSolvers(registry);
  std::string why;
  EXPECT_EQ(registry.Create("lm_magic", {}, &why), nullptr);
  EXPECT_NE(why.find("unknown solver 'lm_magic'"), std::string::npos);
  EXPECT_EQ(registry.Create("nlopt:LN_NOPE", {}, &why), nullptr);
  EXPECT_NE(why.find("'LN_NOPE' is not a known nlopt: choice"), std::string::npos);
  EXPECT_TRUE(registry.Knows("nlopt:GN_CRS2_LM"));
  EXPECT_TRUE(registry.Knows("lm_l2"));
  EXPECT_FALSE(registry.Knows("lm_magic"));
}

}  // namespace
}  // namespace anchorbench::estimator
