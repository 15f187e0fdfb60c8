#include "anchorbench/experiments/config.hpp"

#include <gtest/gtest.h>

#include "anchorbench/experiments/input_error.hpp"
#include "temp_dir.hpp"

namespace anchorbench::experiments {
namespace {

// The error message for a config text, or "" if it loads.
std::string ErrorFor(const std::string& yaml) {
  testing::TempDir dir("config");
  const std::string path = dir.Write("c.yaml", yaml);
  try {
    LoadConfig(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Config, ShippedConfigsLoad) {
  const ExperimentConfig config = LoadConfig(std::string(ANCHORBENCH_CONFIG_DIR) + "/tunnel.yaml");
  EXPECT_EQ(config.name, "tunnel");
  EXPECT_EQ(config.scenario.tunnel.num_anchors, 30);
  EXPECT_DOUBLE_EQ(config.estimator.trigger.pdop_threshold, 1.0);
}

TEST(Config, AbsentKeysKeepDefaults) {
  EXPECT_EQ(ErrorFor("seed: 3\n"), "");
  EXPECT_EQ(ErrorFor(""), "");
}

TEST(Config, UnknownKeyNamesItsPath) {
  const std::string error = ErrorFor("scenario:\n  ranging:\n    sigma_rnage_m: 0.1\n");
  EXPECT_NE(error.find("key 'scenario.ranging.sigma_rnage_m': unknown key"), std::string::npos) << error;
  EXPECT_NE(ErrorFor("estimatr: {}\n").find("key 'estimatr': unknown key"), std::string::npos);
}

TEST(Config, ComponentNamesAreCheckedAgainstTheRegistries) {
  EXPECT_EQ(ErrorFor("estimator:\n  triggers: [pdop_true, pdop_ls, timeout]\n  filter: {kind: ransac}\n"), "");
  std::string error = ErrorFor("estimator:\n  triggers: [fixed_window, pdop_best]\n");
  EXPECT_NE(error.find("key 'estimator.triggers': unknown value 'pdop_best' (choices: anchorbench list"), std::string::npos)
      << error;
  error = ErrorFor("estimator:\n  triggers: [timeout, timeout]\n");
  EXPECT_NE(error.find("key 'estimator.triggers': 'timeout' is listed twice"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  triggers: []\n");
  EXPECT_NE(error.find("key 'estimator.triggers': expected at least one name"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  filter: {kind: median}\n");
  EXPECT_NE(error.find("key 'estimator.filter.kind': unknown value 'median' (choices: none, consistency, ransac)"),
            std::string::npos)
      << error;
  error = ErrorFor("estimator:\n  filter: {enabled: false}\n");  // the switch that filter.kind replaced
  EXPECT_NE(error.find("key 'estimator.filter.enabled': unknown key"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  trigger: {evaluate_every: 0}\n");
  EXPECT_NE(error.find("key 'estimator.trigger.evaluate_every'"), std::string::npos) << error;
}

TEST(Config, WrongTypeNamesItsPath) {
  const std::string error = ErrorFor("scenario:\n  tunnel:\n    num_anchors: many\n");
  EXPECT_NE(error.find("key 'scenario.tunnel.num_anchors': expected an integer, got 'many'"), std::string::npos)
      << error;
  EXPECT_NE(ErrorFor("estimator:\n  nls:\n    l2_warm_start: maybe\n").find("expected true or false"), std::string::npos);
  EXPECT_NE(ErrorFor("scenario: 5\n").find("key 'scenario': expected a mapping"), std::string::npos);
}

TEST(Config, OutOfRangeValuesNameTheirPath) {
  EXPECT_NE(ErrorFor("scenario:\n  ranging:\n    sigma_range_m: -0.1\n").find("key 'scenario.ranging.sigma_range_m': must be >= 0"),
            std::string::npos);
  EXPECT_NE(ErrorFor("estimator:\n  filter:\n    tau_m: -1\n").find("key 'estimator.filter.tau_m'"), std::string::npos);
  EXPECT_NE(ErrorFor("estimator:\n  trigger:\n    pdop_threshold: 0\n").find("key 'estimator.trigger.pdop_threshold': must be > 0"),
            std::string::npos);
  EXPECT_NE(ErrorFor("scenario:\n  ranging:\n    sigma_range_m: .nan\n").find("must be finite"), std::string::npos);
  EXPECT_NE(ErrorFor("scenario:\n  ranging:\n    outlier_probability: 1.5\n").find("outlier_probability"),
            std::string::npos);
  EXPECT_NE(ErrorFor("scenario:\n  trajectory:\n    kind: spiral\n").find("unknown value 'spiral' (choices: random"),
            std::string::npos);
}

TEST(Config, CrossFieldChecksNameTheirSection) {
  const std::string error = ErrorFor("scenario:\n  tunnel:\n    anchor_height_min_m: 4\n    anchor_height_max_m: 2\n");
  EXPECT_NE(error.find("key 'scenario.tunnel': anchor heights"), std::string::npos) << error;
}

TEST(Config, SyntaxErrorNamesTheLine) {
  const std::string error = ErrorFor("seed: 1\nscenario:\n  tunnel: [1, 2\n");
  EXPECT_NE(error.find(".yaml:"), std::string::npos);
  EXPECT_NE(error.find("YAML syntax error"), std::string::npos) << error;
}

TEST(Config, RowsOverlayTheBaseAndNameTheirPath) {
  testing::TempDir dir("rows");
  const std::string path = dir.Write("t.yaml",
                                     "scenario:\n  ranging: {sigma_range_m: 0.2, outlier_probability: 0.1}\n"
                                     "rows:\n  - name: a\n  - name: b\n    scenario: {ranging: {sigma_range_m: 0.5}}\n");
  const ExperimentConfig config = LoadConfig(path);
  ASSERT_EQ(config.rows.size(), 2u);
  EXPECT_EQ(config.rows[0].scenario.ranging.sigma_range_m, 0.2);
  EXPECT_EQ(config.rows[1].scenario.ranging.sigma_range_m, 0.5);
  EXPECT_EQ(config.rows[1].scenario.ranging.outlier_probability, 0.1);  // inherited from the base
  EXPECT_NE(ErrorFor("rows:\n  - scenario: {tunnel: {num_anchors: 0}}\n").find("key 'rows[0].scenario.tunnel.num_anchors'"),
            std::string::npos);
  EXPECT_NE(ErrorFor("realizations: 0\n").find("key 'realizations': must be in [1"), std::string::npos);
  EXPECT_NE(ErrorFor("rows: 3\n").find("key 'rows': expected a list"), std::string::npos);
}

TEST(Config, OverridesAreValidatedLikeTheFile) {
  testing::TempDir dir("set");
  const std::string path = dir.Write("t.yaml", "scenario:\n  tunnel: {width_m: 8}\n");
  const ExperimentConfig config = LoadConfig(path, {"scenario.tunnel.width_m=12", "estimator.trigger.pdop_threshold=0.5"});
  EXPECT_EQ(config.scenario.tunnel.width_m, 12.0);
  EXPECT_EQ(config.estimator.trigger.pdop_threshold, 0.5);
  auto error_for = [&](const std::string& assignment) {
    try {
      LoadConfig(path, {assignment});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_for("scenario.tunnel.widht_m=3").find("key 'scenario.tunnel.widht_m': unknown key"), std::string::npos);
  EXPECT_NE(error_for("scenario.tunnel.width_m=-3").find("must be > 0"), std::string::npos);
  EXPECT_NE(error_for("scenario.tunnel").find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(error_for("scenario.tunnel.width_m.x=1").find("'width_m' is not a section"), std::string::npos);
  EXPECT_NE(error_for("seed.x=1").find("key 'seed': expected an integer"), std::string::npos);

  const std::string table = dir.Write("rows.yaml", "rows:\n  - name: a\n  - name: b\n");
  const ExperimentConfig rows = LoadConfig(table, {"rows.1.scenario.ranging.sigma_range_m=0.3"});
  EXPECT_EQ(rows.rows[0].scenario.ranging.sigma_range_m, 0.1);
  EXPECT_EQ(rows.rows[1].scenario.ranging.sigma_range_m, 0.3);
  EXPECT_THROW(LoadConfig(table, {"rows.2.scenario.ranging.sigma_range_m=0.3"}), InputError);
}

TEST(Config, SolverByRegistryName) {
  testing::TempDir dir("solver");
  EXPECT_EQ(LoadConfig(dir.Write("a.yaml", "estimator: {solver: nlopt:LN_BOBYQA}\n")).estimator.solver_name,
            "nlopt:LN_BOBYQA");
  EXPECT_NE(ErrorFor("estimator: {solver: lm_magic}\n").find("key 'estimator.solver': unknown value 'lm_magic'"),
            std::string::npos);
}

TEST(Config, MissingFileIsAnInputError) {
  EXPECT_THROW(LoadConfig("/nonexistent/config.yaml"), InputError);
}

TEST(Config, ResolvedYamlReadsBackToTheSameConfig) {
  ExperimentConfig config = LoadConfig(std::string(ANCHORBENCH_CONFIG_DIR) + "/tunnel.yaml");
  testing::TempDir dir("roundtrip");
  const std::string path = dir.Write("tunnel.yaml", ToYaml(config));
  const ExperimentConfig again = LoadConfig(path);
  EXPECT_EQ(ToYaml(again), ToYaml(config));
  EXPECT_EQ(again.scenario.ranging.outlier_probability, config.scenario.ranging.outlier_probability);
  EXPECT_EQ(again.estimator.solver.nls.kernel, config.estimator.solver.nls.kernel);
}

}  // namespace
}  // namespace anchorbench::experiments
