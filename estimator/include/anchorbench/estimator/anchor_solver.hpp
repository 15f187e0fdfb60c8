#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>

#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/nls_solver.hpp"
#include "anchorbench/estimator/scaled_solver.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

struct AnchorSolverOptions {
  LsOptions ls;
  NlsOptions nls;
  std::optional<HeightPrior> height_prior;  // one anchor's known height, in both the LS and the NLS
  ScaleOptions scale;                        // a range scale factor as a fifth unknown (ScaledSolver)

  bool IsValid(std::string* why) const {
    return ls.IsValid(why) && nls.IsValid(why) && (!height_prior || height_prior->IsValid(why)) && scale.IsValid(why);
  }
};

// Sec. III-D in full: the double-difference LS coarse solution seeds the NLS refinement.
class AnchorSolver : public Solver {
 public:
  explicit AnchorSolver(const AnchorSolverOptions& options = {},
                        std::shared_ptr<const LogPartitionTable> table = nullptr)
      : options_(options), nls_(options.nls, std::move(table)) {}

  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override {
    const SolveResult coarse = SolveDoubleDifferenceLs(p_world_tag, range_m, options_.ls, options_.height_prior);
    if (!Succeeded(coarse.status)) return coarse;
    return nls_.Solve(p_world_tag, range_m, coarse.p_world_anchor, coarse.bias_m, options_.height_prior);
  }
  // The refinement alone, from the previous estimate: it is already in the basin the LS would seed.
  SolveResult SolveNear(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                        const SolveResult& previous) const override {
    return nls_.Solve(p_world_tag, range_m, previous.p_world_anchor, previous.bias_m, options_.height_prior);
  }
  std::optional<HeightPrior> height_prior() const override { return options_.height_prior; }

 private:
  AnchorSolverOptions options_;
  NlsSolver nls_;
};

}  // namespace anchorbench::estimator
