#include "anchorbench/experiments/scenario_files.hpp"

#include "anchorbench/experiments/atomic_file.hpp"
#include "anchorbench/experiments/csv_reader.hpp"
#include "anchorbench/experiments/input_error.hpp"
#include "anchorbench/experiments/output_folder.hpp"

namespace anchorbench::experiments {

void WriteScenarioFiles(const sim::Scenario& scenario, const std::filesystem::path& folder) {
  CreateFolder(folder);

  AtomicFile poses(folder / "poses.csv");
  poses.stream() << "t,tag_id,x,y,z\n";
  for (std::size_t k = 0; k < scenario.t_s.size(); ++k) {
    for (std::size_t tag = 0; tag < scenario.p_world_tag_reported.size(); ++tag) {
      const Eigen::Vector3d& p = scenario.p_world_tag_reported[tag][k];
      poses.stream() << FormatNumber(scenario.t_s[k]) << ',' << tag << ',' << FormatNumber(p.x()) << ','
                     << FormatNumber(p.y()) << ',' << FormatNumber(p.z()) << '\n';
    }
  }
  AtomicFile ranges(folder / "ranges.csv");
  ranges.stream() << "t,tag_id,anchor_id,range\n";
  for (const sim::SimRange& r : scenario.ranges) {
    ranges.stream() << FormatNumber(r.t_s) << ',' << r.tag_id << ',' << r.anchor_id << ',' << FormatNumber(r.range_m)
                    << '\n';
  }
  AtomicFile anchors(folder / "anchors.csv");
  anchors.stream() << "anchor_id,x,y,z,bias\n";
  for (const sim::SimAnchor& a : scenario.anchors) {
    const Eigen::Vector3d& p = a.p_world_anchor;
    anchors.stream() << a.id << ',' << FormatNumber(p.x()) << ',' << FormatNumber(p.y()) << ',' << FormatNumber(p.z())
                     << ',' << FormatNumber(a.bias_m) << '\n';
  }
  poses.Commit();
  ranges.Commit();
  anchors.Commit();
}

}  // namespace anchorbench::experiments
