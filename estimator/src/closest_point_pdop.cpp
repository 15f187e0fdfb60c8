#include "anchorbench/estimator/closest_point_pdop.hpp"

namespace anchorbench::estimator {

Eigen::Matrix3d ClosestPointPdop::Information() const {
  Eigen::Matrix3d information;
  information << s2_[0], s2_[1], s2_[2],  //
      s2_[1], s2_[3], s2_[4],             //
      s2_[2], s2_[4], s2_[5];
  return information;
}

double ClosestPointPdop::HorizontalValue() const {
  if (count_ < 4) return std::numeric_limits<double>::infinity();  // as Value(), so the two compare
  return HdopFromBlock(s2_[0], s2_[1], s2_[3]);
}

double ClosestPointPdop::BiasAwareValue() const {
  if (count_ < 4) return std::numeric_limits<double>::infinity();
  return BiasAwareDopFromSums(Information(), t1_, static_cast<double>(count_));
}

}  // namespace anchorbench::estimator
