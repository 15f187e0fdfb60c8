#pragma once

#include <map>
#include <ostream>
#include <span>

#include "anchorbench/schema/attempt.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::io {

// The interchange formats written (recorded_data.hpp reads them back): a header, then one row per
// record, numbers as the shortest text that reads back to the same double.
void WritePoses(std::ostream& out, std::span<const PoseRecord> poses);
void WriteRanges(std::ostream& out, std::span<const RangeRecord> ranges);
// The bias column appears when at least one anchor has a bias.
void WriteAnchors(std::ostream& out, const std::map<int, schema::AnchorTruth>& anchors);

// poses.csv, ranges.csv and anchors.csv into the folder.
void WriteRecording(ResultFolder& folder, const Recording& recording);
// The same as a result folder of its own, whole or absent (ResultFolder: `overwrite`, `inputs`).
void WriteRecordingFolder(const std::filesystem::path& folder, const Recording& recording, bool overwrite,
                          const std::vector<std::filesystem::path>& inputs);

// One realization as a recording: the *reported* tag positions (with sigma_position_m noise: what
// a robot's navigation would log), the ranges, and the truth (with bias).
Recording RecordingOf(const sim::Scenario& scenario);

}  // namespace anchorbench::io
