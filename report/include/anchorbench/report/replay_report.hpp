#pragma once

#include <ostream>
#include <vector>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/schema/attempt.hpp"

namespace anchorbench::report {

// estimates.csv: anchor_id,method,initialized,t_init,n_used,pdop_est,pdop_true,x,y,z,bias,err_m,status,err_xy,err_z
void WriteEstimates(std::ostream& out, const std::vector<schema::Attempt>& attempts);
// The same, aligned for a terminal.
void PrintEstimates(std::ostream& out, const std::vector<schema::Attempt>& attempts);

// trace.csv: one line per range handed to the initializers, the first trigger's view of it.
constexpr const char* kTraceHeader = "t,tag_id,anchor_id,range,accepted,n_accepted,pdop";
void WriteTraceRow(std::ostream& out, const io::RangeRecord& range, const estimator::FeedResult& fed);

}  // namespace anchorbench::report
