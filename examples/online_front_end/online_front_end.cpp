// A recorded log streamed through the online front end one message at a time, as a ROS node's
// callbacks would see it: a pose callback and a range callback, and an idle step that runs the
// deferred solves outside the callbacks. Prints every initialization as it happens.
//   online_front_end poses.csv ranges.csv
// It links the estimator core alone: typed options, no names, no files. The two CSVs (the
// formats of `anchorbench simulate`, README "Formats") stand in for the topics; a robot's driver
// would deliver the messages instead, so this reader checks only what it needs.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "anchorbench/estimator/front_end.hpp"

namespace est = anchorbench::estimator;

namespace {

// The rows of a CSV of `columns` numbers after its header line; a bad row names the file and line.
std::vector<std::vector<double>> ReadRows(const char* path, std::size_t columns) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(std::string(path) + ": cannot open");
  std::vector<std::vector<double>> rows;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (number == 1) continue;  // the header
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) {
      std::size_t used = 0;
      try {
        row.push_back(std::stod(cell, &used));
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || !std::isfinite(row.back())) break;
    }
    if (row.size() != columns) {
      throw std::runtime_error(std::string(path) + ":" + std::to_string(number) + ": expected " +
                               std::to_string(columns) + " numbers");
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

// What a navigation stack would hold: the front end, built once with the paper's chain per anchor.
class AnchorInitNode {
 public:
  // Solves run in Idle(), never inside a sensor callback.
  static est::FrontEndOptions Deferred() {
    est::FrontEndOptions options;
    options.defer_solves = true;
    return options;
  }

  // The adaptive kernel's table is built here, once, not in the first range callback.
  AnchorInitNode()
      : table_(est::DefaultLogPartitionTable()),
        front_end_(
            [this](int anchor_id) {
              est::PaperChainOptions options;
              options.filter.tau_m = 0.2;  // ~2 sigma_d for 0.1 m range noise
              std::vector<est::AnchorInitializer> chains;
              chains.push_back(est::MakePaperInitializer(anchor_id, options, table_));
              return chains;
            },
            Deferred()) {}

  void OnPose(double t_s, int tag_id, const Eigen::Vector3d& p_world_tag) { front_end_.AddPose(t_s, tag_id, p_world_tag); }
  void OnRange(double t_s, int tag_id, int anchor_id, double range_m) {
    front_end_.AddRange(t_s, tag_id, anchor_id, range_m);
  }
  // Between callbacks: the solves, then what they produced.
  void Idle() {
    front_end_.RunPendingSolves();
    for (const est::FrontEndEvent& event : front_end_.TakeEvents()) Print(event);
  }
  void Shutdown(double t_s) {
    front_end_.Finish(t_s);
    for (const est::FrontEndEvent& event : front_end_.TakeEvents()) Print(event);
    const est::FrontEndCounters& c = front_end_.counters();
    std::printf("fed %ld ranges; dropped %ld outside the poses, %ld without a pose in time\n", c.samples,
                c.ranges_outside_poses, c.ranges_without_pose);
  }

 private:
  static void Print(const est::FrontEndEvent& e) {
    const est::SolveResult& s = e.init.solve;
    std::printf("t=%7.2f s  anchor %3d  %-10s  p=(%.3f, %.3f, %.3f) m  bias %.3f m  sd %.3f m  PDOP %.2f  %d samples\n",
                e.init.t_s, e.anchor_id, std::string(est::ToString(s.status)).c_str(), s.p_world_anchor.x(),
                s.p_world_anchor.y(), s.p_world_anchor.z(), s.bias_m,
                std::sqrt(s.covariance.topLeftCorner<3, 3>().trace()), e.init.pdop_closest_point, e.init.n_used);
  }

  std::shared_ptr<const est::LogPartitionTable> table_;
  est::FrontEnd front_end_;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: online_front_end poses.csv ranges.csv\n");
    return 2;
  }
  try {
    const std::vector<std::vector<double>> poses = ReadRows(argv[1], 5);   // t,tag_id,x,y,z
    const std::vector<std::vector<double>> ranges = ReadRows(argv[2], 4);  // t,tag_id,anchor_id,range
    AnchorInitNode node;
    // The log's messages in arrival order (a pose before a range of the same time), one at a time.
    std::size_t i = 0, j = 0;
    double t_s = 0.0;
    while (i < poses.size() || j < ranges.size()) {
      if (j == ranges.size() || (i < poses.size() && poses[i][0] <= ranges[j][0])) {
        const std::vector<double>& pose = poses[i++];
        t_s = pose[0];
        node.OnPose(t_s, static_cast<int>(pose[1]), Eigen::Vector3d(pose[2], pose[3], pose[4]));
        node.Idle();
      } else {
        const std::vector<double>& range = ranges[j++];
        t_s = range[0];
        node.OnRange(t_s, static_cast<int>(range[1]), static_cast<int>(range[2]), range[3]);
      }
    }
    node.Shutdown(t_s);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "online_front_end: %s\n", e.what());
    return 2;
  }
  return 0;
}
