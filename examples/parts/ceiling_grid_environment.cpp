// An example of an environment of one's own: a warehouse aisle's box with its anchors on a grid
// under the ceiling, rows along its length and columns across. A body wanders inside as in the
// hall (trajectory.cpp's HallTrajectory). Named `scenario.environment: ceiling_grid`, its options
// are the section `scenario.ceiling_grid` (swept as scenario.ceiling_grid.rows, ...).
#include <memory>
#include <string>

#include "anchorbench/example_parts/example_parts.hpp"
#include "anchorbench/sim/environment_model.hpp"

namespace anchorbench::example_parts {
namespace {

struct CeilingGridOptions {
  double length_m = 30.0;
  double width_m = 12.0;
  double height_m = 6.0;
  int rows = 3;     // anchors along the length
  int columns = 2;  // anchors across

  bool IsValid(std::string* why) const {
    const char* problem = !(length_m > 0.0 && length_m <= 1e4)   ? "length_m must be in (0, 1e4]"
                          : !(width_m > 0.0 && width_m <= 1e4)   ? "width_m must be in (0, 1e4]"
                          : !(height_m > 0.0 && height_m <= 1e4) ? "height_m must be in (0, 1e4]"
                          : !(rows >= 1 && rows <= 100)          ? "rows must be in [1, 100]"
                          : !(columns >= 1 && columns <= 100)    ? "columns must be in [1, 100]"
                                                                 : nullptr;
    if (problem && why) *why = problem;
    return problem == nullptr;
  }
};

template <typename V>
void VisitOptions(V& v, CeilingGridOptions& o) {
  v.Number("length_m", o.length_m, "the box's length (m)");
  v.Number("width_m", o.width_m, "its width (m)");
  v.Number("height_m", o.height_m, "its height: the anchors hang there (m)");
  v.Integer("rows", o.rows, "anchors along the length");
  v.Integer("columns", o.columns, "anchors across");
}

class CeilingGrid : public sim::Environment {
 public:
  explicit CeilingGrid(const CeilingGridOptions& options) : o_(options) {
    as_hall_.length_m = o_.length_m;
    as_hall_.width_m = o_.width_m;
    as_hall_.height_m = o_.height_m;
  }

  bool IsValid(const sim::TrajectoryOptions& trajectory, std::string* why) const override {
    if (trajectory.kind == sim::TrajectoryKind::kApproach) {
      if (why) *why = "trajectory.kind approach is the hall's (ceiling_grid has none)";
      return false;
    }
    return o_.IsValid(why);
  }
  int NumAnchors() const override { return o_.rows * o_.columns; }
  // Cell centres of the grid; the layout stream is not drawn from (the grid is fixed).
  std::vector<Eigen::Vector3d> Anchors(sim::RandomStream&) const override {
    std::vector<Eigen::Vector3d> anchors;
    for (int row = 0; row < o_.rows; ++row) {
      for (int column = 0; column < o_.columns; ++column) {
        anchors.emplace_back((row + 0.5) * o_.length_m / o_.rows, (column + 0.5) * o_.width_m / o_.columns, o_.height_m);
      }
    }
    return anchors;
  }
  sim::Trajectory Path(const sim::TrajectoryOptions& trajectory, std::span<const Eigen::Vector3d>,
                       sim::RandomStream& shape) const override {
    return sim::HallTrajectory(as_hall_, trajectory, shape);
  }
  double LongestRun_s(const sim::TrajectoryOptions& trajectory) const override { return trajectory.hall_duration_s; }
  Box Bounds() const override { return {Eigen::Vector3d::Zero(), Eigen::Vector3d(o_.length_m, o_.width_m, o_.height_m)}; }

 private:
  CeilingGridOptions o_;
  sim::HallOptions as_hall_;  // the box HallTrajectory wanders in
};

}  // namespace

void RegisterCeilingGridEnvironment(registry::EnvironmentRegistry& environments) {
  environments.RegisterWithOptions<CeilingGridOptions>(
      "ceiling_grid", "a box with its anchors on a grid under the ceiling (an example environment)",
      [](const CeilingGridOptions& options, const registry::EnvironmentContext&) {
        return std::make_unique<CeilingGrid>(options);
      });
}

}  // namespace anchorbench::example_parts
