#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "anchorbench/estimator/enum_names.hpp"

namespace anchorbench::estimator {

// How a solve ended. Numerical failure is a status, never an exception.
enum class SolveStatus {
  kConverged,           // step and kernel shape stopped changing (see NlsOptions tolerances)
  kMaxIterations,       // iteration budget spent; the estimate is the best one reached
  kNoConvergence,       // stopped without a trustworthy minimum (e.g. on the edge of a search box)
  kTooFewSamples,       // fewer samples than unknowns (4) plus one
  kDegenerateGeometry,  // normal equations numerically singular (e.g. collinear tag positions)
  kNumericalFailure,    // a non-finite value appeared; no estimate
  kHeightUnobservable,  // the estimate's mirror through the tags' plane fits as well (HeightCheckedSolver)
  kBudgetSpent,         // the caller's work budget ran out first (NlsOptions::max_passes): no trusted estimate
};

inline constexpr EnumNames<SolveStatus, 8> kSolveStatusNames({
    {SolveStatus::kConverged, "converged"}, {SolveStatus::kMaxIterations, "max_iterations"},
    {SolveStatus::kNoConvergence, "no_convergence"}, {SolveStatus::kTooFewSamples, "too_few_samples"},
    {SolveStatus::kDegenerateGeometry, "degenerate_geometry"}, {SolveStatus::kNumericalFailure, "numerical_failure"},
    {SolveStatus::kHeightUnobservable, "height_unobservable"}, {SolveStatus::kBudgetSpent, "budget_spent"}});
inline std::string_view ToString(SolveStatus value) { return kSolveStatusNames.Name(value); }
inline bool Succeeded(SolveStatus s) {
  return s == SolveStatus::kConverged || s == SolveStatus::kMaxIterations;
}

// A fit against another of the same data (the mirror check's two tests: height_check.hpp; the
// certificate's alternatives): both tests' numbers, and when more of the same data would pass them
// (ours). The separation lambda is the evidence the data give on average where the first fit is
// the anchor (its expectation under the noise model), and at a geometry that goes on as it has it
// grows in proportion to the samples.
struct FitComparison {
  double evidence = 0.0;           // for the first fit over the other (FitEvidence)
  double evidence_needed = 0.0;    // e.g. HeightCheckOptions::min_evidence
  double separation = 0.0;         // lambda of the two fits (Separation); +infinity: a height prior alone separates them
  double separation_needed = 0.0;  // e.g. HeightCheckOptions::min_separation
  std::size_t samples = 0;         // the samples judged
  // What a range error outside the noise model (the certificate's model error) could make of the
  // second fit's extra squares, in the evidence's units: already taken off `evidence`. Where
  // evidence + explained reaches evidence_needed but evidence does not, the second fit is worse,
  // and only the model error keeps it in.
  double explained = 0.0;
  bool separated() const { return separation >= separation_needed; }
  // The samples at which both tests would pass if each number went on growing in proportion to
  // the samples (the evidence at its own rate, lambda at the geometry's); +infinity where one does
  // not grow: the mirror fits as well, or no worse than the model error could explain (evidence
  // <= 0), or the path is flat (lambda ~ 0). Then more height in the path, or a height prior,
  // settles it, not more of the same.
  double SamplesNeeded() const;
};

// Anchor position and range bias theta = (p_A, gamma) with its summary, after Ceres' Summary.
struct SolveResult {
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  double bias_m = 0.0;
  double alpha = 2.0;  // kernel shape in use at the end (2 = L2)
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();  // of (p_A, gamma), m^2
  SolveStatus status = SolveStatus::kNumericalFailure;
  int iterations = 0;
  double final_cost = 0.0;  // sum of rho(r_k / c, alpha), Eq. (12)
  // The range scale s of d = (1 + s) |p_U - p_A| + gamma, where it was estimated and observable
  // (ScaledSolver); 0 and sigma 0 otherwise.
  double range_scale = 0.0;
  double range_scale_sigma = 0.0;
  // A height prior's information 1 / sigma_z^2 (m^-2) in the covariance, 0 without one: what the
  // covariance knows beside the ranges, for whoever rescales its range part (credible_covariance.hpp).
  double height_information = 0.0;
  // The prior's weight beside one unit-weight range in the refinement (the NLS: c^2 / sigma_z^2),
  // which decides how far a range error moves the height; 0 without a prior or where the solver
  // weighs it otherwise (the LS alone: its model error then ignores the prior, the cautious side).
  double height_weight = 0.0;
  std::optional<FitComparison> mirror_refusal;  // status kHeightUnobservable from the mirror check: its comparison
};

}  // namespace anchorbench::estimator
