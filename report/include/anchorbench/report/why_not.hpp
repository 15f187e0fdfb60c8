#pragma once
// Why an anchor is not initialized yet, as the attempts' and estimates' files write it, and the
// certificate's judgements as a trace (replay --certificate-trace): docs/real_data.md.

#include <optional>
#include <ostream>
#include <string>

#include "anchorbench/estimator/init_trigger.hpp"

namespace anchorbench::report {

// "blocked_by,value,limit": the test's name and its numbers; empty fields where there is none.
std::string WhyNotFields(const std::optional<estimator::Judgement>& judgement);

// The certificate trace: one row per evaluation of a trigger that solves.
constexpr const char* kJudgementColumns =
    "t,anchor_id,method,samples,blocked_by,value,limit,region_m,share_noise,share_correlation,share_model_error,"
    "share_travel_bias,share_link_offsets,share_tag_offsets,evidence,evidence_needed,evidence_explained,stability_m,"
    "samples_needed";
void WriteJudgementRow(std::ostream& out, int anchor_id, const std::string& method, const estimator::Judgement& j);

}  // namespace anchorbench::report
