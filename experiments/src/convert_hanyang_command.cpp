#include <iostream>

#include "anchorbench/experiments/commands.hpp"
#include "anchorbench/experiments/hanyang.hpp"

namespace anchorbench::experiments {

int ConvertHanyangCommand(const ConvertHanyangArgs& args) {
  const HanyangSummary s = ConvertHanyangCase(args.case_folder, args.out);
  std::cout << "convert-hanyang: " << s.poses << " poses, " << s.ranges << " ranges, " << s.anchors << " anchors -> "
            << args.out;
  if (s.dropped_poses > 0) std::cout << " (" << s.dropped_poses << " trajectory rows with non-increasing time dropped)";
  std::cout << '\n';
  return 0;
}

}  // namespace anchorbench::experiments
