// An example of a part that owns its options: a trigger that fires once the tag has travelled far
// enough around the anchor, measured as the extent of the box around its accepted positions. A
// geometry-blind baseline between a sample count and the closest-point PDOP: it knows how much
// ground was covered, not in which directions the anchor was seen.
//
// Everything the part needs is in this file: its options (read from `estimator.travel_span`,
// swept as `estimator.travel_span.span_m`, listed by `anchorbench list`), the trigger, and its
// registration, called from example_parts.cpp.
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/example_parts/example_parts.hpp"

namespace anchorbench::example_parts {
namespace {

struct TravelSpanOptions {
  double span_m = 10.0;
  double vertical_span_m = 0.0;

  bool IsValid(std::string* why) const {
    const char* problem = !(span_m > 0.0)             ? "span_m must be > 0"
                          : !(vertical_span_m >= 0.0) ? "vertical_span_m must be >= 0"
                                                      : nullptr;
    if (problem && why) *why = problem;
    return problem == nullptr;
  }
};

template <typename V>
void VisitOptions(V& v, TravelSpanOptions& o) {
  v.Number("span_m", o.span_m, "fire once the box around the tag's accepted positions is this long, diagonally (m)");
  v.Number("vertical_span_m", o.vertical_span_m, "and at least this tall (m; 0: any height)");
}

// O(1) a sample: the box grows with each accepted position.
class TravelSpanTrigger : public estimator::InitTrigger {
 public:
  explicit TravelSpanTrigger(const TravelSpanOptions& options) : options_(options) {}

  bool Fire(const estimator::TriggerInput& in) override {
    low_ = seen_ ? low_.cwiseMin(in.sample_p_world_tag) : in.sample_p_world_tag;
    high_ = seen_ ? high_.cwiseMax(in.sample_p_world_tag) : in.sample_p_world_tag;
    seen_ = true;
    last_t_s_ = in.t_s;
    samples_ = in.n_admitted;
    return in.eligible && Span() >= options_.span_m && Height() >= options_.vertical_span_m;
  }

  std::optional<estimator::Judgement> why_not() const override {
    if (!seen_) return std::nullopt;
    estimator::Judgement judgement;
    judgement.t_s = last_t_s_;
    judgement.samples = samples_;
    const bool short_of_span = Span() < options_.span_m;
    judgement.blocked_by = short_of_span ? "travel_span" : "travel_height";
    judgement.value = short_of_span ? Span() : Height();
    judgement.limit = short_of_span ? options_.span_m : options_.vertical_span_m;
    return judgement;
  }

 private:
  double Span() const { return (high_ - low_).norm(); }
  double Height() const { return high_.z() - low_.z(); }

  TravelSpanOptions options_;
  bool seen_ = false;
  Eigen::Vector3d low_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d high_ = Eigen::Vector3d::Zero();
  double last_t_s_ = 0.0;
  std::size_t samples_ = 0;
};

}  // namespace

void RegisterTravelSpanTrigger(registry::TriggerRegistry& triggers) {
  triggers.RegisterWithOptions<TravelSpanOptions>(
      "travel_span", "fires once the tag's accepted positions span estimator.travel_span.span_m (an example part)",
      [](const TravelSpanOptions& options, const registry::TriggerContext&) {
        return std::make_unique<TravelSpanTrigger>(options);
      });
}

}  // namespace anchorbench::example_parts
