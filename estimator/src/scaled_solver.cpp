#include "anchorbench/estimator/scaled_solver.hpp"

#include <cmath>
#include <vector>

namespace anchorbench::estimator {
namespace {

constexpr double kStep = 0.005;  // h: 0.5% of every range

struct AtScale {
  SolveResult solve;  // in the world's units: the bias is gamma, not gamma / (1 + s)
  double cost = 0.0;  // C(s) = sum ((1 + s) |p_k - p_A| + gamma - d_k)^2
};

AtScale SolveAt(const Solver& inner, std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                double scale, std::vector<double>& scaled) {
  for (std::size_t k = 0; k < range_m.size(); ++k) scaled[k] = range_m[k] / (1.0 + scale);
  AtScale at{inner.Solve(p_world_tag, scaled), 0.0};
  if (!Succeeded(at.solve.status)) return at;
  at.solve.bias_m *= 1.0 + scale;
  at.solve.covariance.row(3) *= 1.0 + scale;
  at.solve.covariance.col(3) *= 1.0 + scale;
  for (std::size_t k = 0; k < range_m.size(); ++k) {
    const double r = (1.0 + scale) * (p_world_tag[k] - at.solve.p_world_anchor).norm() + at.solve.bias_m - range_m[k];
    at.cost += r * r;
  }
  return at;
}

}  // namespace

bool ScaleOptions::IsValid(std::string* why) const {
  if (!(max_sigma > 0.0 && max_sigma <= 1.0)) {
    if (why) *why = "max_sigma must be in (0, 1]";
    return false;
  }
  if (!(max_scale > 0.0 && max_scale <= 0.5)) {
    if (why) *why = "max_scale must be in (0, 0.5]";
    return false;
  }
  return true;
}

SolveResult ScaledSolver::Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const {
  if (!options_.estimate) return inner().Solve(p_world_tag, range_m);
  std::vector<double> scaled(range_m.size());
  const AtScale middle = SolveAt(inner(), p_world_tag, range_m, 0.0, scaled);
  if (!Succeeded(middle.solve.status) || range_m.size() <= 5) return middle.solve;
  const AtScale low = SolveAt(inner(), p_world_tag, range_m, -kStep, scaled);
  const AtScale high = SolveAt(inner(), p_world_tag, range_m, kStep, scaled);
  if (!Succeeded(low.solve.status) || !Succeeded(high.solve.status)) return middle.solve;
  // The parabola C(s) = a s^2 + b s + c through the three.
  const double a = (high.cost + low.cost - 2.0 * middle.cost) / (2.0 * kStep * kStep);
  const double b = (high.cost - low.cost) / (2.0 * kStep);
  const double variance = middle.cost / static_cast<double>(range_m.size() - 5);
  if (!(a > 0.0) || !(variance > 0.0)) return middle.solve;
  const double vertex = -b / (2.0 * a);
  const double sigma = std::sqrt(variance / a);
  if (!(sigma <= options_.max_sigma) || !(std::abs(vertex) <= options_.max_scale)) return middle.solve;
  AtScale best = SolveAt(inner(), p_world_tag, range_m, vertex, scaled);
  if (!Succeeded(best.solve.status)) return middle.solve;
  // The estimate's dependence on s, from the two side solves, carries sigma_s into its covariance.
  Eigen::Vector4d slope;
  slope << (high.solve.p_world_anchor - low.solve.p_world_anchor) / (2.0 * kStep),
      (high.solve.bias_m - low.solve.bias_m) / (2.0 * kStep);
  best.solve.covariance += sigma * sigma * slope * slope.transpose();
  best.solve.range_scale = vertex;
  best.solve.range_scale_sigma = sigma;
  return best.solve;
}

}  // namespace anchorbench::estimator
