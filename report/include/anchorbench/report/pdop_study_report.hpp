#pragma once

#include <ostream>
#include <string>

#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/schema/pdop_study.hpp"

namespace anchorbench::report {

// pdop_trace.csv: one line per checkpoint: realization,anchor_id,n,t,pdop_closest_point,pdop_ls,
// pdop_nls,pdop_true,bias_aware_dop,ls_err_m,nls_err_m.
void WritePdopTrace(std::ostream& out, const std::vector<schema::PdopCheckpoint>& checkpoints);

// pdop_study.md: how often the closest-point PDOP underestimates the true one (Theorem 3.1), the
// PDOP estimates against the truth per time bin of `bin_s` (Fig. 7), and each PDOP as the trigger
// (Figs. 7-8).
void WritePdopStudyMarkdown(std::ostream& out, const schema::ExperimentConfig& config, const schema::PdopStudy& study,
                            int every, double bin_s);

}  // namespace anchorbench::report
