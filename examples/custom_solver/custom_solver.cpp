// A solver of one's own, registered beside the built-ins and run on the same trials as the
// paper's: the LS coarse solution followed by a Cauchy-kernel refinement started from the median
// of a few LS solutions on disjoint thirds of the data ("ls_thirds_cauchy"). Prints one line per
// solver: the paper's trigger's mean error and initializations.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "anchorbench/estimator/components.hpp"
#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/monte_carlo.hpp"
#include "anchorbench/experiments/summary.hpp"

namespace est = anchorbench::estimator;
namespace ex = anchorbench::experiments;

class ThirdsCauchySolver : public est::Solver {
 public:
  explicit ThirdsCauchySolver(const est::AnchorSolverOptions& options) : options_(options) {
    options_.nls.kernel = est::KernelMode::kFixed;
    options_.nls.fixed_alpha = 0.0;
  }

  est::SolveResult Solve(std::span<const Eigen::Vector3d> p, std::span<const double> d) const override {
    const std::size_t third = d.size() / 3;
    std::vector<Eigen::Vector3d> seeds;
    std::vector<double> biases;
    for (std::size_t i = 0; i < 3; ++i) {
      const auto part = est::SolveDoubleDifferenceLs(p.subspan(i * third, third), d.subspan(i * third, third));
      if (est::Succeeded(part.status)) {
        seeds.push_back(part.p_world_anchor);
        biases.push_back(part.bias_m);
      }
    }
    if (seeds.empty()) return est::SolveDoubleDifferenceLs(p, d, options_.ls);  // its failure status
    Eigen::Vector3d median;
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> values;
      for (const auto& s : seeds) values.push_back(s[axis]);
      std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
      median[axis] = values[values.size() / 2];
    }
    std::nth_element(biases.begin(), biases.begin() + biases.size() / 2, biases.end());
    return est::NlsSolver(options_.nls).Solve(p, d, median, biases[biases.size() / 2]);
  }

 private:
  est::AnchorSolverOptions options_;
};

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: custom_solver CONFIG (e.g. configs/table1.yaml)\n");
    return 2;
  }
  est::Components components;
  est::RegisterBuiltins(components);
  components.solvers.Register("ls_thirds_cauchy", "median of LS on thirds, then a Cauchy-kernel LM",
                              [](const std::string&, const est::SolverContext& context) {
                                return std::make_unique<ThirdsCauchySolver>(context.options);
                              });
  ex::ExperimentConfig config = ex::LoadConfig(argv[1]);
  config.realizations = 5;
  for (const char* solver : {"lm_adaptive", "ls_thirds_cauchy"}) {
    for (ex::RowConfig& row : config.rows) row.estimator.solver_name = solver;
    const auto attempts = ex::RunMonteCarlo(config, {2, nullptr, &components});
    const auto rows = ex::RowsOf(config);
    const auto summaries = ex::Summarize(attempts, rows, config.realizations, 0, config.seed);
    for (const auto& s : summaries) {
      if (s.method != ex::kPaperTrigger) continue;
      std::printf("%-18s row %-8s gated: %4d initialized, mean error %s m\n", solver, rows[s.row].name.c_str(), s.init,
                  s.avg_m ? std::to_string(*s.avg_m).c_str() : "-");
    }
  }
  return 0;
}
