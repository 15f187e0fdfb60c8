// A part's own section of the config: estimator.<part>, read with the part's keys, checked by its
// rule, filled with its defaults where the part is named, written back, swept like any key.
#include <gtest/gtest.h>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/schema/input_error.hpp"
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

std::string ErrorFor(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
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
  EXPECT_NE(ErrorFor("estimator: {my_wait: {wait_s: -1}}\n").find("key 'estimator.my_wait.wait_s': must be > 0, got '-1'"),
            std::string::npos)
      << ErrorFor("estimator: {my_wait: {wait_s: -1}}\n");
  EXPECT_NE(ErrorFor("estimator: {my_wait: {min_count: 2.5}}\n").find("estimator.my_wait.min_count"), std::string::npos);
  EXPECT_NE(ErrorFor("estimator: {my_wait: {wait: 3}}\n").find("key 'estimator.my_wait.wait': unknown key"),
            std::string::npos)
      << ErrorFor("estimator: {my_wait: {wait: 3}}\n");
  EXPECT_NE(ErrorFor("estimator: {my_wait: {wait_s: soon}}\n").find("expected a number"), std::string::npos);
  EXPECT_NE(ErrorFor("seed: 1\n", {"estimator.my_wait.wait_s=0"}).find("estimator.my_wait.wait_s"), std::string::npos);
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

}  // namespace
}  // namespace anchorbench::config
