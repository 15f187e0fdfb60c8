// A part's own section of the config: estimator.<part>, read with the part's keys, checked by its
// rule, filled with its defaults where the part is named, written back, swept like any key.
#include <gtest/gtest.h>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/sim/scenario.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::config {
namespace {

struct WaitOptions {
  double wait_s = 5.0;
  int min_count = 10;
  bool IsValid(std::string* why) const {
    if (wait_s > 0.0) return true;
    if (why) *why = "wait_s must be > 0";
    return false;
  }
};

template <typename V>
void VisitOptions(V& v, WaitOptions& o) {
  v.Number("wait_s", o.wait_s, "how long it waits (s)");
  v.Integer("min_count", o.min_count, "and how many samples");
}

const registry::Components& WithWaitTrigger() {
  static const registry::Components components = [] {
    registry::Components parts = eval::MakeComponentsWithOracles();
    parts.triggers.RegisterWithOptions<WaitOptions>("my_wait", "waits", [](const WaitOptions& o, const registry::TriggerContext&) {
      return std::make_unique<estimator::TimeoutTrigger>(o.wait_s);
    });
    return parts;
  }();
  return components;
}

std::string PartErrorFor(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  try {
    LoadConfigText(yaml, "c.yaml", overrides, WithWaitTrigger());
  } catch (const schema::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PartOptionsConfig, APartsSectionIsReadAndItsDefaultsFilledWhereItIsNamed) {
  const auto loaded = LoadConfigText("estimator:\n  triggers: [my_wait]\n  my_wait: {wait_s: 2.5}\n", "c.yaml", {},
                                     WithWaitTrigger());
  const schema::PartOptionValues& own = loaded.estimator.part_options.at("my_wait");
  EXPECT_EQ(own.at("wait_s"), 2.5);
  EXPECT_EQ(own.at("min_count"), 10.0);  // the default, so the resolved config shows it
  // Not named and not set: no section.
  EXPECT_TRUE(LoadConfigText("seed: 1\n", "c.yaml", {}, WithWaitTrigger()).estimator.part_options.empty());
}

TEST(PartOptionsConfig, AnOverrideOrASweepAxisSetsAPartsKey) {
  const auto loaded = LoadConfigText("estimator: {triggers: [my_wait]}\nrows: [{name: a}, {name: b, estimator: {my_wait: {wait_s: 9}}}]\n",
                                     "c.yaml", {"estimator.my_wait.wait_s=4"}, WithWaitTrigger());
  EXPECT_EQ(loaded.estimator.part_options.at("my_wait").at("wait_s"), 4.0);
  ASSERT_EQ(loaded.rows.size(), 2u);
  EXPECT_EQ(loaded.rows[0].estimator.part_options.at("my_wait").at("wait_s"), 4.0);
  EXPECT_EQ(loaded.rows[1].estimator.part_options.at("my_wait").at("wait_s"), 4.0);  // the override reaches rows
}

TEST(PartOptionsConfig, BadValuesNameTheKeyAndThePartsRule) {
  EXPECT_NE(PartErrorFor("estimator: {my_wait: {wait_s: -1}}\n").find("key 'estimator.my_wait.wait_s': must be > 0, got '-1'"),
            std::string::npos)
      << PartErrorFor("estimator: {my_wait: {wait_s: -1}}\n");
  EXPECT_NE(PartErrorFor("estimator: {my_wait: {min_count: 2.5}}\n").find("estimator.my_wait.min_count"), std::string::npos);
  EXPECT_NE(PartErrorFor("estimator: {my_wait: {wait: 3}}\n").find("key 'estimator.my_wait.wait': unknown key"),
            std::string::npos)
      << PartErrorFor("estimator: {my_wait: {wait: 3}}\n");
  EXPECT_NE(PartErrorFor("estimator: {my_wait: {wait_s: soon}}\n").find("expected a number"), std::string::npos);
  EXPECT_NE(PartErrorFor("seed: 1\n", {"estimator.my_wait.wait_s=0"}).find("estimator.my_wait.wait_s"), std::string::npos);
}

TEST(PartOptionsConfig, TheResolvedConfigCarriesThePartsSectionAndReadsBackTheSame) {
  const auto loaded = LoadConfigText("estimator:\n  triggers: [my_wait]\n  my_wait: {wait_s: 2.5}\n", "c.yaml", {},
                                     WithWaitTrigger());
  const std::string yaml = ToYaml(loaded);
  EXPECT_NE(yaml.find("my_wait:"), std::string::npos) << yaml;
  EXPECT_EQ(ToYaml(LoadConfigText(yaml, "again.yaml", {}, WithWaitTrigger())), yaml);
}

TEST(PartOptionsConfig, APartMayNotTakeTheNameOfAnEstimatorKey) {
  registry::Components components = eval::MakeComponentsWithOracles();
  components.triggers.RegisterWithOptions<WaitOptions>("certificate", "shadows a section",
                                                        [](const WaitOptions& o, const registry::TriggerContext&) {
                                                          return std::make_unique<estimator::TimeoutTrigger>(o.wait_s);
                                                        });
  try {
    LoadConfigText("seed: 1\n", "c.yaml", {}, components);
    FAIL() << "a part named like the certificate's section was accepted";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the part 'certificate' owns options but has the name of a key"),
              std::string::npos)
        << e.what();
  }
}

// An environment of the caller's: a line of anchors `count` long, 5 m apart, wandered through as
// the hall is.
struct LineOptions {
  int count = 3;
};

template <typename V>
void VisitOptions(V& v, LineOptions& o) {
  v.Integer("count", o.count, "anchors");
}

class Line : public sim::Environment {
 public:
  explicit Line(int count) : count_(count) {}
  bool IsValid(const sim::TrajectoryOptions&, std::string* why) const override {
    if (count_ >= 1) return true;
    if (why) *why = "count must be >= 1";
    return false;
  }
  int NumAnchors() const override { return count_; }
  std::vector<Eigen::Vector3d> Anchors(sim::RandomStream&) const override {
    std::vector<Eigen::Vector3d> anchors;
    for (int i = 0; i < count_; ++i) anchors.emplace_back(5.0 * i, 0.0, 3.0);
    return anchors;
  }
  sim::Trajectory Path(const sim::TrajectoryOptions& trajectory, std::span<const Eigen::Vector3d>,
                       sim::RandomStream& shape) const override {
    return sim::HallTrajectory(sim::HallOptions{}, trajectory, shape);
  }
  double LongestRun_s(const sim::TrajectoryOptions& trajectory) const override { return trajectory.hall_duration_s; }
  Box Bounds() const override { return {Eigen::Vector3d::Zero(), Eigen::Vector3d(40.0, 20.0, 8.0)}; }

 private:
  int count_;
};

const registry::Components& WithLine() {
  static const registry::Components components = [] {
    registry::Components parts = eval::MakeComponentsWithOracles();
    parts.environments.RegisterWithOptions<LineOptions>(
        "line", "anchors in a line", [](const LineOptions& o, const registry::EnvironmentContext&) {
          return std::make_unique<Line>(o.count);
        });
    return parts;
  }();
  return components;
}

schema::ExperimentConfig LoadWithLine(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  return LoadConfigText(yaml, "c.yaml", overrides, WithLine());
}

TEST(EnvironmentConfig, ARegisteredEnvironmentIsBuiltFromItsSectionAndRowsMayChangeIt) {
  const auto loaded = LoadWithLine(
      "scenario: {environment: line, line: {count: 4}}\nrows: [{name: a}, {name: b, scenario: {line: {count: 6}}},"
      " {name: c, scenario: {environment: hall}}]\n");
  EXPECT_EQ(loaded.scenario.NumAnchors(), 4);
  EXPECT_EQ(loaded.rows[0].scenario.NumAnchors(), 4);
  EXPECT_EQ(loaded.rows[1].scenario.NumAnchors(), 6);
  EXPECT_EQ(loaded.rows[2].scenario.EnvironmentName(), "hall");
  EXPECT_EQ(loaded.rows[2].scenario.NumAnchors(), sim::HallOptions{}.num_anchors);
  EXPECT_EQ(sim::GenerateScenario(loaded.rows[1].scenario, 1, 0).anchors.size(), 6u);
  // Swept like any key, and written into the resolved config, which reads back the same.
  EXPECT_EQ(LoadWithLine("scenario: {environment: line}\n", {"scenario.line.count=9"}).scenario.NumAnchors(), 9);
  const std::string yaml = ToYaml(loaded);
  EXPECT_NE(yaml.find("environment: line"), std::string::npos) << yaml;
  EXPECT_EQ(ToYaml(LoadWithLine(yaml)), yaml);
}

TEST(EnvironmentConfig, AnUnknownEnvironmentOrABadOptionNamesItsKey) {
  const auto error = [](const std::string& yaml) {
    try {
      LoadWithLine(yaml);
    } catch (const schema::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("scenario: {environment: mine}\n").find("key 'scenario.environment': unknown environment 'mine'"),
            std::string::npos)
      << error("scenario: {environment: mine}\n");
  EXPECT_NE(error("scenario: {environment: line, line: {count: 1.5}}\n").find("scenario.line.count"), std::string::npos);
  EXPECT_NE(error("scenario: {environment: line, line: {count: 0}}\n").find("count must be >= 1"), std::string::npos)
      << error("scenario: {environment: line, line: {count: 0}}\n");
}

}  // namespace
}  // namespace anchorbench::config
