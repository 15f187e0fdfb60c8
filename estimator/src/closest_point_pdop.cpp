#include "anchorbench/estimator/closest_point_pdop.hpp"

#include <limits>

#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::estimator {

void ClosestPointPdop::Add(const Eigen::Vector3d& p_world_tag, double range_m) {
  if (count_ == 0) origin_ = p_world_tag;
  const Eigen::Vector3d p = p_world_tag - origin_;
  const double w = 1.0 / (range_m * range_m);  // row scaling 1/d_k of Eq. (4), squared
  s0_ += w;
  s1_ += w * p;
  s2_ += w * p * p.transpose();
  if (count_ == 0 || range_m < min_range_m_) {
    min_range_m_ = range_m;
    p_closest_ = p;
  }
  ++count_;
}

Eigen::Matrix3d ClosestPointPdop::Information() const {
  const Eigen::Matrix3d cross = s1_ * p_closest_.transpose();
  // Eq. (6) expanded around p_C.
  return s2_ - cross - cross.transpose() + s0_ * p_closest_ * p_closest_.transpose();
}

double ClosestPointPdop::Value() const {
  if (count_ < 4) return std::numeric_limits<double>::infinity();  // G~ needs >= 3 rows
  return PdopFromInformation(Information());
}

}  // namespace anchorbench::estimator
