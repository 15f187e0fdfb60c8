#include <iostream>

#include "anchorbench/io/hanyang.hpp"
#include "anchorbench/io/scenario_files.hpp"
#include "commands.hpp"

namespace anchorbench::app {

int ConvertHanyangCommand(const ConvertHanyangArgs& args) {
  const io::HanyangCase converted = io::ConvertHanyangCase(args.case_folder);
  const io::Recording& r = converted.recording;
  io::WriteRecordingFolder(args.out, r, args.overwrite, {args.case_folder});
  std::cout << "convert-hanyang: " << r.poses.size() << " poses, " << r.ranges.size() << " ranges, " << r.anchors.size()
            << " anchors -> " << args.out;
  if (converted.dropped_poses > 0) {
    std::cout << " (" << converted.dropped_poses << " trajectory rows with non-increasing time dropped)";
  }
  std::cout << '\n';
  return 0;
}

}  // namespace anchorbench::app
