#pragma once

#include <memory>
#include <optional>
#include <span>

#include <Eigen/Core>

#include "anchorbench/estimator/height_prior.hpp"
#include "anchorbench/estimator/solve_result.hpp"

namespace anchorbench::estimator {

// The fewest samples each solve accepts (fewer: SolveStatus::kTooFewSamples).
// Double-difference LS: 4 unknowns (p_A, gamma), one sample spent as the pivot of Eqs. (9)-(10),
// and one redundant row so the residual variance of the covariance has a degree of freedom.
constexpr int kMinSamplesLs = 6;
// Nonlinear refinement: 4 unknowns and one degree of freedom for s^2 = sum w r^2 / (N - 4).
constexpr int kMinSamplesNls = 5;

// A solver for (p_A, gamma) from tag positions and ranges. Implementations report failure through
// SolveResult::status (never an exception, never a non-finite estimate with a success status).
class Solver {
 public:
  virtual ~Solver() = default;
  virtual SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const = 0;
  // The same solve for data close to those `previous` was solved from (the tag-offset alternation:
  // the ranges less slightly different offsets), which a solver may start from instead of from
  // scratch. By default it solves from scratch.
  virtual SolveResult SolveNear(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                                const SolveResult& /*previous*/) const {
    return Solve(p_world_tag, range_m);
  }
  // The anchor's known height this solver weighs, if any. The solver is the one place an anchor's
  // prior is held: the mirror check and the certificate read it from here.
  virtual std::optional<HeightPrior> height_prior() const { return std::nullopt; }
};

// A solver around another one, which it calls (once or many times) and whose result it checks or
// extends: ScaledSolver (the range scale), RansacSolver (consensus subsets), HeightCheckedSolver
// (the mirror). Each takes the inner solver first, then its options. An initializer stacks them
// in one order, inner to outer: the named solver, ScaledSolver (registry::MakeInitializer, with
// AnchorSolverOptions::scale), RansacSolver (the filter's solve stage, OutlierFilter::AtSolve),
// HeightCheckedSolver (InitializerOptions::height_check).
class SolverDecorator : public Solver {
 protected:
  explicit SolverDecorator(std::shared_ptr<const Solver> inner) : inner_(std::move(inner)) {}
  const Solver& inner() const { return *inner_; }

 public:
  std::optional<HeightPrior> height_prior() const override { return inner_->height_prior(); }

 private:
  std::shared_ptr<const Solver> inner_;
};

}  // namespace anchorbench::estimator
