// Every registered solver side by side on the same samples, and a plain Eigen dense least-squares
// baseline, so that a reader sees ratios rather than absolute times (scripts/benchmarks.sh turns
// this program's output into results/benchmarks/solvers.csv). Each solver also reports its
// position error on that data (error_m), so speed is read next to what it buys.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/registry/components.hpp"
#include "bench_data.hpp"

namespace {

namespace est = anchorbench::estimator;
namespace registry = anchorbench::registry;

// The textbook baseline: multilateration without bias, linearized by subtracting the first
// range equation, |p_k - p_A|^2 - |p_0 - p_A|^2 = d_k^2 - d_0^2, i.e. rows
// 2 (p_k - p_0)^T p_A = |p_k|^2 - |p_0|^2 - d_k^2 + d_0^2, solved densely by column-pivoting
// Householder QR on the (N-1) x 3 matrix: what one writes with Eigen and no further thought.
Eigen::Vector3d DenseEigenLs(const std::vector<Eigen::Vector3d>& p, const std::vector<double>& d) {
  const Eigen::Index rows = static_cast<Eigen::Index>(p.size()) - 1;
  Eigen::MatrixXd a(rows, 3);
  Eigen::VectorXd b(rows);
  for (Eigen::Index k = 0; k < rows; ++k) {
    const Eigen::Vector3d& p_k = p[static_cast<std::size_t>(k) + 1];
    const double d_k = d[static_cast<std::size_t>(k) + 1];
    a.row(k) = 2.0 * (p_k - p[0]).transpose();
    b(k) = p_k.squaredNorm() - p[0].squaredNorm() - d_k * d_k + d[0] * d[0];
  }
  return a.colPivHouseholderQr().solve(b);
}

// Benchmark arguments: N samples, the outlier share in percent.
anchorbench::bench::PassByAnchor Data(const benchmark::State& state) {
  return anchorbench::bench::MakePassByAnchor(static_cast<std::size_t>(state.range(0)),
                                              static_cast<double>(state.range(1)) / 100.0);
}

void BM_EigenDenseLs(benchmark::State& state) {
  const auto data = Data(state);
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  for (auto _ : state) {
    p_world_anchor = DenseEigenLs(data.p_world_tag, data.range_m);
    benchmark::DoNotOptimize(p_world_anchor);
  }
  state.counters["error_m"] = (p_world_anchor - data.p_world_anchor).norm();
}

std::shared_ptr<const est::Solver> Registered(const std::string& name, std::string* why) {
  static registry::Components components = [] {
    registry::Components c;
    registry::RegisterBuiltins(c);
    return c;
  }();
  registry::SolverContext context;
  context.tables = components.tables.get();
  return components.solvers.Create(name, context, why);
}

void Measure(benchmark::State& state, const est::Solver& solver) {
  const auto data = Data(state);
  est::SolveResult result;
  for (auto _ : state) {
    result = solver.Solve(data.p_world_tag, data.range_m);
    benchmark::DoNotOptimize(result);
  }
  state.counters["error_m"] = (result.p_world_anchor - data.p_world_anchor).norm();
  state.counters["solver_iterations"] = result.iterations;
}

void BM_Solver(benchmark::State& state, const std::string& name) {
  std::string why;
  const auto solver = Registered(name, &why);
  if (!solver) {
    state.SkipWithError(why.c_str());
    return;
  }
  Measure(state, *solver);
}

// RANSAC around lm_adaptive, in each scheme: ours (the default) and the Table II baseline
// (p = 0.95, s = 60, e = 0.1: 1666 subsets, each solved in full).
void BM_Ransac(benchmark::State& state, est::RansacScheme scheme) {
  est::RansacOptions options;
  options.scheme = scheme;
  if (scheme == est::RansacScheme::kFullSolve) {
    options.success_probability = 0.95;
    options.subset_size = 60;
  }
  std::string why;
  const est::RansacSolver ransac(Registered("lm_adaptive", &why), options, 1);
  Measure(state, ransac);
}

// A pass at 10 Hz (600), longer logs, and 10^4 (the buffer's scale), each at 5, 10 and 20% outliers.
void Sizes(benchmark::internal::Benchmark* b) {
  for (const int outlier_percent : {5, 10, 20}) {
    for (const int n : {600, 2400, 10000}) b->Args({n, outlier_percent});
  }
  b->ArgNames({"n", "outlier_percent"})->Unit(benchmark::kMillisecond);
}

const int kRegistered = [] {
  BENCHMARK(BM_EigenDenseLs)->Apply(Sizes);
  for (const char* name : {"ls_single", "ls_double", "lm_l2", "lm_huber", "lm_cauchy", "lm_adaptive",
                           "nlopt:LN_BOBYQA"}) {
    benchmark::RegisterBenchmark((std::string("BM_Solver/") + name).c_str(), BM_Solver, std::string(name))
        ->Apply(Sizes);
  }
  for (const auto scheme : {est::RansacScheme::kMinimal, est::RansacScheme::kFullSolve}) {
    const std::string name = "BM_Solver/ransac_" + std::string(est::ToString(scheme)) + "(lm_adaptive)";
    benchmark::RegisterBenchmark(name.c_str(), BM_Ransac, scheme)->Apply(Sizes);
  }
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
