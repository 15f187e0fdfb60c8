// A solver of one's own, registered beside the built-ins and named in a config file like them:
// the LS coarse solution followed by a Cauchy-kernel refinement started from the median of a few
// LS solutions on disjoint thirds of the data ("ls_thirds_cauchy"). Runs the config as given, then
// with the paper's solver on the same trials, and prints the paper's trigger's mean error and
// initializations per row for both.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/engine/monte_carlo.hpp"

namespace est = anchorbench::estimator;
namespace ab = anchorbench;

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
    std::fprintf(stderr, "usage: custom_solver CONFIG (e.g. examples/custom_solver/table1_thirds.yaml)\n");
    return 2;
  }
  // The registries are ours: the built-ins, the oracles, and our solver.
  ab::registry::Components components = ab::eval::MakeComponentsWithOracles();
  components.solvers.Register("ls_thirds_cauchy", "median of LS on thirds, then a Cauchy-kernel LM",
                              [](const std::string&, const ab::registry::SolverContext& context) {
                                return std::make_unique<ThirdsCauchySolver>(context.options);
                              });
  try {
    const ab::schema::ExperimentConfig ours = ab::config::LoadConfig(argv[1], {}, components);
    const ab::schema::ExperimentConfig paper = ab::config::LoadConfig(argv[1], {"estimator.solver=lm_adaptive"}, components);
    for (const ab::schema::ExperimentConfig* config : {&ours, &paper}) {
      const auto attempts = ab::engine::RunMonteCarlo(*config, components, {2, nullptr});
      const auto rows = ab::schema::RowsOf(*config);
      for (const auto& s : ab::report::Summarize(attempts, rows, config->realizations, 0, config->seed)) {
        if (s.method != ab::schema::kPaperTrigger) continue;
        std::printf("%-18s row %-8s gated: %4d initialized, mean error %s m\n", config->estimator.solver.c_str(),
                    rows[s.row].name.c_str(), s.init, s.avg_m ? std::to_string(*s.avg_m).c_str() : "-");
      }
    }
  } catch (const ab::schema::InputError& e) {
    std::fprintf(stderr, "custom_solver: %s\n", e.what());
    return 2;
  }
  return 0;
}
