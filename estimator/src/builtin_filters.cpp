#include "anchorbench/estimator/filter_registry.hpp"

namespace anchorbench::estimator {
namespace {

// RANSAC as the pre-filter of the paper's Table II: nothing online; at solve time the solver
// runs inside RANSAC (subsets, consensus, final fit on the inliers).
class RansacFilter : public OutlierFilter {
 public:
  RansacFilter(const RansacOptions& options, std::uint64_t seed) : options_(options), seed_(seed) {}

  bool Accept(const RangeSample&) override { return true; }
  std::shared_ptr<const Solver> AtSolve(std::shared_ptr<const Solver> solver) const override {
    return std::make_shared<RansacSolver>(options_, std::move(solver), seed_);
  }

 private:
  RansacOptions options_;
  std::uint64_t seed_;
};

}  // namespace

void RegisterBuiltinFilters(FilterRegistry& registry) {
  registry.Register("none", "every range accepted (the do-nothing baseline)",
                    [](const std::string&, const FilterContext&) { return std::make_unique<NullFilter>(); });
  registry.Register("consistency", "the triangle-inequality check of Sec. III-B, online (filter.tau_m)",
                    [](const std::string&, const FilterContext& context) {
                      return std::make_unique<ConsistencyFilter>(context.options.consistency);
                    });
  registry.Register("ransac", "RANSAC around the solver at solve time (Jung et al. 2024; Table II; filter.ransac)",
                    [](const std::string&, const FilterContext& context) {
                      return std::make_unique<RansacFilter>(context.options.ransac, context.seed);
                    });
}

}  // namespace anchorbench::estimator
