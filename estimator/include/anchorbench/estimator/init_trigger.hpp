#pragma once

#include <span>
#include <string>

#include <Eigen/Core>


namespace anchorbench::estimator {

// What a trigger sees after every accepted sample of its anchor, until the anchor is initialized.
struct TriggerInput {
  double t_s = 0.0;        // this sample's time
  double t_first_s = 0.0;  // the anchor's first accepted sample
  std::span<const Eigen::Vector3d> p_world_tag;  // the accepted samples so far, this one last
  std::span<const double> range_m;
  double pdop = 0.0;  // the closest-point PDOP of Eq. (4) over them (+inf if undefined)
  // Whether the initializer would solve if the trigger fired now (min_samples reached, not waiting
  // for more data after a failed solve). Costly triggers evaluate only then; all may update state.
  bool eligible = false;
};

// When to initialize an anchor (Sec. III-C): one interface, so the paper's comparisons (closest-
// point PDOP vs the PDOP at the LS or NLS estimate vs the true PDOP vs a fixed window) are a
// configuration choice. One instance per anchor; it may keep state between samples.
class InitTrigger {
 public:
  virtual ~InitTrigger() = default;

  // Called after every accepted sample until the anchor is initialized: true to solve now.
  virtual bool Fire(const TriggerInput& input) = 0;

  // False for the fixed-window baseline: it never fires online, and the initializer solves once,
  // on all of the anchor's data, at Finish().
  virtual bool online() const { return true; }
};

// The paper's trigger (Sec. III-C): the closest-point PDOP of Eq. (4) below a threshold, O(1).
class ClosestPointPdopTrigger : public InitTrigger {
 public:
  explicit ClosestPointPdopTrigger(double threshold) : threshold_(threshold) {}
  bool Fire(const TriggerInput& in) override { return in.eligible && in.pdop < threshold_; }

 private:
  double threshold_;
};

struct TriggerOptions {
  double pdop_threshold = 1.0;  // pdop_*: fire once the PDOP is below this (Sec. IV-A uses 1)
  int sample_count = 300;       // sample_count: fire at this many accepted samples
  double timeout_s = 30.0;      // timeout: fire this long after the anchor's first accepted sample
  // pdop_ls, pdop_nls: solve for the estimate every this many accepted samples. Each solve is
  // O(N), so solving at every sample would make an anchor O(N^2).
  int evaluate_every = 10;

  bool IsValid(std::string* why) const;
};

}  // namespace anchorbench::estimator
