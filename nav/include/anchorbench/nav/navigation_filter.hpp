#pragma once
// The navigation filter of the downstream study (ours, docs/navigation.md): an EKF on the tag's
// position p (3), the odometry's velocity bias b (3) and its heading error delta_psi (1), driven
// by odometry steps (odometry.hpp inverts to p+ = p + Rz(-delta_psi) (d - b dt)), and corrected by
// ranges d = |p - p_A| + gamma to anchors an initializer reported.
//
// An anchor's uncertainty is carried as Schmidt consider states: each anchor's (p_A, gamma) joins
// the state with the covariance its initialization reported and no correlation to the rest, and
// is never updated, while the cross-covariances it builds with the tag are kept. So repeated
// ranges to one wrongly placed anchor do not average its error away, and the filter's covariance
// stays honest; dropping the consider states (anchor covariance 0) makes it overconfident
// (navigation_filter_test.cpp measures both).

#include <map>

#include <Eigen/Core>

#include "anchorbench/nav/odometry.hpp"

namespace anchorbench::nav {

class NavigationFilter {
 public:
  static constexpr int kTagStates = 7;  // p (3), b (3), delta_psi (1)

  // Starts at `p_world_tag` with `sigma_position_m` per axis, no bias and no heading error
  // (odometry's errors start at zero), propagated with `drift`'s random walks.
  NavigationFilter(const Eigen::Vector3d& p_world_tag, double sigma_position_m, const OdometryDrift& drift);

  void Predict(const OdometryStep& step);

  // An anchor from its initialization: position and range bias with their covariance (4 x 4,
  // of (p_A, gamma)), as consider states. A second call for one id is ignored. A
  // `horizontal_only` anchor (its height mirror-ambiguous: both mirrors through a flat path's
  // plane predict the same range there) corrects the tag's x-y alone: the update's vertical
  // columns, whose sign the mirror leaves unknown, are dropped.
  void AddAnchor(int anchor_id, const Eigen::Vector3d& p_world_anchor, double bias_m,
                 const Eigen::Matrix4d& covariance, bool horizontal_only = false);
  bool HasAnchor(int anchor_id) const { return anchors_.count(anchor_id) > 0; }

  // A range to a known anchor; false (state untouched) for an unknown anchor or an innovation
  // beyond the chi-square gate (1 dof; infinite: no gate).
  bool UpdateRange(int anchor_id, double range_m, double sigma_range_m, double gate_chi2);

  Eigen::Vector3d position() const { return x_.head<3>(); }
  Eigen::Matrix3d position_covariance() const { return P_.topLeftCorner<3, 3>(); }
  double heading_error() const { return x_[6]; }

 private:
  void ResizeScratch();

  OdometryDrift drift_;
  struct Consider {
    int at = 0;  // index of its first consider state
    bool horizontal_only = false;
  };
  Eigen::VectorXd x_;
  Eigen::MatrixXd P_;
  std::map<int, Consider> anchors_;  // by id
  // Scratch of the state's size, resized when an anchor joins: no allocation per step or range.
  Eigen::MatrixXd J_;             // the step's Jacobian rows (3 x n)
  Eigen::MatrixXd JP_;            // J P (3 x n)
  Eigen::RowVectorXd H_;          // a range's Jacobian
  Eigen::VectorXd PHt_, K_;
};

}  // namespace anchorbench::nav
