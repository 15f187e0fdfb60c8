// libFuzzer harness for the CSV readers: the first byte picks poses.csv, ranges.csv or
// anchors.csv, read strictly or under lenient policies (drops counted, rows sorted in a window,
// repeated poses averaged), the rest is the file. A reader must return records or throw one schema::InputError;
// anything else (a crash, a leak, another exception, undefined behaviour) is a finding.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/recorded_data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  try {
    anchorbench::io::LogPolicy lenient;
    lenient.out_of_order = data[0] & 8 ? anchorbench::io::LogPolicy::OutOfOrder::kSort
                                       : anchorbench::io::LogPolicy::OutOfOrder::kDrop;
    lenient.repeated_poses = anchorbench::io::LogPolicy::RepeatedPoses::kAverage;
    anchorbench::io::LogDrops drops;
    switch (data[0] % 5) {
      case 0: anchorbench::io::ReadPoses(in, "poses.csv"); break;
      case 1: anchorbench::io::ReadRanges(in, "ranges.csv"); break;
      case 2: anchorbench::io::ReadPoses(in, "poses.csv", lenient, &drops); break;
      case 3: anchorbench::io::ReadRanges(in, "anchor_3.csv", lenient, &drops); break;
      default: anchorbench::io::ReadAnchors(in, "anchors.csv"); break;
    }
  } catch (const anchorbench::schema::InputError&) {
  }
  return 0;
}
