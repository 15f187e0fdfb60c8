#include "anchorbench/report/why_not.hpp"

#include <cmath>

#include "anchorbench/io/format.hpp"

namespace anchorbench::report {
namespace {

std::string Cell(double value) { return std::isnan(value) ? std::string() : io::FormatNumber(value); }

}  // namespace

std::string WhyNotFields(const std::optional<estimator::Judgement>& judgement) {
  if (!judgement || judgement->blocked_by.empty()) return ",,";
  return std::string(judgement->blocked_by) + "," + Cell(judgement->value) + "," + Cell(judgement->limit);
}

void WriteJudgementRow(std::ostream& out, int anchor_id, const std::string& method, const estimator::Judgement& j) {
  out << Cell(j.t_s) << ',' << anchor_id << ',' << method << ',' << j.samples << ','
      << (j.blocked_by.empty() ? std::string_view("fired") : j.blocked_by) << ',' << Cell(j.value) << ','
      << Cell(j.limit) << ',' << Cell(j.region_m) << ',' << Cell(j.share_noise) << ',' << Cell(j.share_correlation)
      << ',' << Cell(j.share_model_error) << ',' << Cell(j.share_travel_bias) << ',' << Cell(j.share_link_offsets)
      << ',' << Cell(j.share_tag_offsets) << ',' << Cell(j.evidence) << ',' << Cell(j.evidence_needed) << ','
      << Cell(j.evidence_explained) << ',' << Cell(j.stability_m) << ',' << Cell(j.samples_needed) << '\n';
}

}  // namespace anchorbench::report
