// A recorded log streamed through the online front end one message at a time, as a ROS node's
// callbacks would see it: a pose callback and a range callback, and an idle step that runs the
// deferred solves outside the callbacks. Prints every initialization as it happens.
//   online_front_end poses.csv ranges.csv
// The estimator core is all this needs at run time: typed options, no names, no files.
#include <cmath>
#include <cstdio>
#include <vector>

#include "anchorbench/estimator/front_end.hpp"
#include "anchorbench/io/input_error.hpp"
#include "anchorbench/io/recorded_data.hpp"

namespace est = anchorbench::estimator;
namespace io = anchorbench::io;

namespace {

// What a navigation stack would hold: the front end, built once with the paper's chain per anchor.
class AnchorInitNode {
 public:
  // Solves run in Idle(), never inside a sensor callback.
  static est::FrontEndOptions Deferred() {
    est::FrontEndOptions options;
    options.defer_solves = true;
    return options;
  }

  AnchorInitNode()
      : tables_(std::make_shared<est::LogPartitionTables>()),
        front_end_(
            [this](int anchor_id) {
              est::PaperChainOptions options;
              options.filter.tau_m = 0.2;  // ~2 sigma_d for 0.1 m range noise
              std::vector<est::AnchorInitializer> chains;
              chains.push_back(est::MakePaperInitializer(anchor_id, options, tables_->Get(10.0, -10.0)));
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
                std::sqrt(s.covariance.topLeftCorner<3, 3>().trace()), e.init.pdop_estimate, e.init.n_used);
  }

  std::shared_ptr<est::LogPartitionTables> tables_;
  est::FrontEnd front_end_;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: online_front_end poses.csv ranges.csv\n");
    return 2;
  }
  try {
    const std::vector<io::PoseRecord> poses = io::LoadPoses(argv[1]);
    const std::vector<io::RangeRecord> ranges = io::LoadRanges(argv[2]);
    AnchorInitNode node;
    // The log's messages in arrival order (a pose before a range of the same time), one at a time.
    std::size_t i = 0, j = 0;
    double t_s = 0.0;
    while (i < poses.size() || j < ranges.size()) {
      if (j == ranges.size() || (i < poses.size() && poses[i].t_s <= ranges[j].t_s)) {
        t_s = poses[i].t_s;
        node.OnPose(t_s, poses[i].tag_id, poses[i].p_world_tag);
        ++i;
        node.Idle();
      } else {
        t_s = ranges[j].t_s;
        node.OnRange(t_s, ranges[j].tag_id, ranges[j].anchor_id, ranges[j].range_m);
        ++j;
      }
    }
    node.Shutdown(t_s);
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "online_front_end: %s\n", e.what());
    return 2;
  }
  return 0;
}
