#include <iostream>

#include "anchorbench/io/hanyang.hpp"
#include "commands.hpp"

namespace anchorbench::app {

int ConvertHanyangCommand(const ConvertHanyangArgs& args) {
  const io::HanyangSummary s = io::ConvertHanyangCase(args.case_folder, args.out);
  std::cout << "convert-hanyang: " << s.poses << " poses, " << s.ranges << " ranges, " << s.anchors << " anchors -> "
            << args.out;
  if (s.dropped_poses > 0) std::cout << " (" << s.dropped_poses << " trajectory rows with non-increasing time dropped)";
  std::cout << '\n';
  return 0;
}

}  // namespace anchorbench::app
