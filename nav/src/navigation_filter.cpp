#include "anchorbench/nav/navigation_filter.hpp"

#include <cmath>

namespace anchorbench::nav {
namespace {

// d Rz(-angle) / d angle.
Eigen::Matrix3d YawDerivative(double angle_rad) {
  const double c = std::cos(-angle_rad), s = std::sin(-angle_rad);
  Eigen::Matrix3d d;
  d << s, c, 0.0, -c, s, 0.0, 0.0, 0.0, 0.0;  // -(d Rz(theta) / d theta) at theta = -angle
  return d;
}

}  // namespace

NavigationFilter::NavigationFilter(const Eigen::Vector3d& p_world_tag, double sigma_position_m,
                                   const OdometryDrift& drift)
    : drift_(drift), x_(Eigen::VectorXd::Zero(kTagStates)), P_(Eigen::MatrixXd::Zero(kTagStates, kTagStates)) {
  x_.head<3>() = p_world_tag;
  P_.topLeftCorner<3, 3>().diagonal().setConstant(sigma_position_m * sigma_position_m);
  ResizeScratch();
}

void NavigationFilter::ResizeScratch() {
  const Eigen::Index n = x_.size();
  J_ = Eigen::MatrixXd::Zero(3, n);
  J_.leftCols<3>().setIdentity();
  JP_.resize(3, n);
  H_.resize(n);
  PHt_.resize(n);
  K_.resize(n);
}

void NavigationFilter::Predict(const OdometryStep& step) {
  const double dt = step.dt_s;
  // The random walks first: the step's heading error and bias are those after this step's walk.
  P_.block<3, 3>(3, 3).diagonal().array() += drift_.sigma_bias_mps_per_sqrt_s * drift_.sigma_bias_mps_per_sqrt_s * dt;
  P_(6, 6) += drift_.sigma_heading_rad_per_sqrt_s * drift_.sigma_heading_rad_per_sqrt_s * dt;
  // Then the step: p+ = p + Rz(-delta_psi) (d - b dt), linearized at the estimate.
  const Eigen::Vector3d b = x_.segment<3>(3);
  const double heading = x_[6];
  const Eigen::Vector3d u = step.displacement_m - b * dt;
  const Eigen::Matrix3d rotation = Yaw(-heading);
  x_.head<3>() += rotation * u;
  // F is the identity but for its first three rows (J, whose columns past the tag's stay zero):
  // F P F^T in O(n^2), rows then columns.
  J_.block<3, 3>(0, 3) = -rotation * dt;
  J_.block<3, 1>(0, 6) = YawDerivative(heading) * u;
  JP_.noalias() = J_ * P_;
  Eigen::Matrix3d top;
  top.noalias() = JP_ * J_.transpose();
  P_.topRows<3>() = JP_;
  P_.leftCols<3>() = JP_.transpose();  // below the top: (P J^T) rows are (J P) columns, P symmetric
  P_.topLeftCorner<3, 3>() = top;
  const double step_variance = drift_.sigma_step_m_per_sqrt_s * drift_.sigma_step_m_per_sqrt_s * dt;
  P_.topLeftCorner<3, 3>() += step_variance * rotation * rotation.transpose();
}

void NavigationFilter::AddAnchor(int anchor_id, const Eigen::Vector3d& p_world_anchor, double bias_m,
                                 const Eigen::Matrix4d& covariance, bool horizontal_only) {
  if (HasAnchor(anchor_id)) return;
  const Eigen::Index at = x_.size();
  x_.conservativeResize(at + 4);
  x_.segment<3>(at) = p_world_anchor;
  x_[at + 3] = bias_m;
  Eigen::MatrixXd grown = Eigen::MatrixXd::Zero(at + 4, at + 4);
  grown.topLeftCorner(at, at) = P_;
  grown.block<4, 4>(at, at) = covariance;
  P_ = std::move(grown);
  anchors_[anchor_id] = {static_cast<int>(at), horizontal_only};
  ResizeScratch();
}

bool NavigationFilter::UpdateRange(int anchor_id, double range_m, double sigma_range_m, double gate_chi2) {
  const auto found = anchors_.find(anchor_id);
  if (found == anchors_.end()) return false;
  const int a = found->second.at;
  const Eigen::Vector3d offset = x_.head<3>() - x_.segment<3>(a);
  const double distance = offset.norm();
  if (!(distance > 1e-6)) return false;
  Eigen::Vector3d direction = offset / distance;
  if (found->second.horizontal_only) direction.z() = 0.0;
  // h = |p - p_A| + gamma; H over the tag's position and the anchor's consider states.
  H_.setZero();
  H_.head<3>() = direction.transpose();
  H_.segment<3>(a) = -direction.transpose();
  H_[a + 3] = 1.0;
  const double innovation = range_m - (distance + x_[a + 3]);
  const double variance = sigma_range_m * sigma_range_m;
  PHt_.noalias() = P_ * H_.transpose();
  const double s = H_.dot(PHt_) + variance;
  if (innovation * innovation / s > gate_chi2) return false;
  // Schmidt: the gain of the tag's states only; the consider states keep their values.
  K_ = PHt_ / s;
  K_.tail(x_.size() - kTagStates).setZero();
  x_ += K_ * innovation;
  // Joseph form, right for any gain (the consider states' zero rows included), in O(n^2):
  // (I - K H) P (I - K H)^T + r K K^T = P - K (PH^T)^T - (PH^T) K^T + (H P H^T + r) K K^T.
  P_.noalias() -= K_ * PHt_.transpose();
  P_.noalias() -= PHt_ * K_.transpose();
  P_.noalias() += s * K_ * K_.transpose();
  return true;
}

}  // namespace anchorbench::nav
