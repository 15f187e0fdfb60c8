#pragma once

#include <memory>

#include "anchorbench/estimator/range_sample.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// An outlier filter for one anchor, in two stages: online, one sample at a time, before the
// trigger sees the sample (the consistency check of Sec. III-B); and at solve time, on the buffer
// (RANSAC, which needs a batch). Each filter does one or the other or, like `none`, neither.
class OutlierFilter {
 public:
  virtual ~OutlierFilter() = default;

  // Online stage: false drops the sample (it is neither buffered nor seen by the trigger).
  virtual bool Accept(const RangeSample& sample) = 0;

  // Solve stage: the solver to run on the accepted samples. A batch filter wraps `solver`;
  // online filters hand it back as it is.
  virtual std::shared_ptr<const Solver> AtSolve(std::shared_ptr<const Solver> solver) const { return solver; }

  // The bias the online stage leaves in the accepted ranges along the direction of travel, in
  // metres, for ranges whose consecutive differences have scale `difference_scale_m`
  // (DifferenceScale in credible_covariance.hpp), at a sample whose motion loosens the filter's
  // test by `slack_m` (TravelBiasOf); 0 for a filter that does not select on range differences.
  virtual double TravelBias(double /*difference_scale_m*/, double /*slack_m*/) const { return 0.0; }
};

// The do-nothing baseline (`none`): every sample accepted, the solver unchanged.
class NullFilter : public OutlierFilter {
 public:
  bool Accept(const RangeSample&) override { return true; }
};

}  // namespace anchorbench::estimator
