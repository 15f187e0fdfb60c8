#include "anchorbench/config/load_config.hpp"

#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/config/load_calibration.hpp"
#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/testing/components.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::config {
namespace {

using schema::InputError;
using schema::ExperimentConfig;
using schema::RowsOf;

using anchorbench::testing::AllComponents;

ExperimentConfig LoadConfig(const std::string& path, const std::vector<std::string>& overrides = {}) {
  return config::LoadConfig(path, overrides, AllComponents());
}

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
  EXPECT_NE(error.find("key 'estimator.triggers': unknown trigger 'pdop_best' (anchorbench list shows the choices)"),
            std::string::npos)
      << error;
  error = ErrorFor("estimator:\n  triggers: [timeout, timeout]\n");
  EXPECT_NE(error.find("key 'estimator.triggers': 'timeout' is listed twice"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  triggers: []\n");
  EXPECT_NE(error.find("key 'estimator.triggers': expected at least one name"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  filter: {kind: median}\n");
  EXPECT_NE(error.find("key 'estimator.filter.kind': unknown filter 'median'"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  filter: {enabled: false}\n");  // the switch that filter.kind replaced
  EXPECT_NE(error.find("key 'estimator.filter.enabled': unknown key"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  trigger: {evaluate_every: 0}\n");
  EXPECT_NE(error.find("key 'estimator.trigger.evaluate_every'"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  trigger: {bias_aware_threshold: 0}\n");
  EXPECT_NE(error.find("key 'estimator.trigger.bias_aware_threshold'"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  trigger: {confidence_sigmas: 11}\n");
  EXPECT_NE(error.find("key 'estimator.trigger.confidence_sigmas'"), std::string::npos) << error;
}

TEST(Config, WrongTypeNamesItsPath) {
  const std::string error = ErrorFor("scenario:\n  tunnel:\n    num_anchors: many\n");
  EXPECT_NE(error.find("key 'scenario.tunnel.num_anchors': expected an integer, got 'many'"), std::string::npos)
      << error;
  EXPECT_NE(ErrorFor("estimator:\n  nls:\n    l2_warm_start: maybe\n").find("expected true or false"), std::string::npos);
  EXPECT_NE(ErrorFor("scenario: 5\n").find("key 'scenario': expected a mapping"), std::string::npos);
}

TEST(Config, OutOfRangeValuesNameTheirPath) {
  EXPECT_NE(ErrorFor("scenario:\n  ranging:\n    sigma_range_m: -0.1\n").find("key 'scenario.ranging.sigma_range_m': must be in [0, 100]"),
            std::string::npos);
  EXPECT_NE(ErrorFor("estimator:\n  filter:\n    tau_m: -1\n").find("key 'estimator.filter.tau_m'"), std::string::npos);
  EXPECT_NE(ErrorFor("estimator:\n  trigger:\n    pdop_threshold: 0\n").find("key 'estimator.trigger.pdop_threshold': must be in (0, 1e6]"),
            std::string::npos);
  EXPECT_NE(ErrorFor("scenario:\n  ranging:\n    sigma_range_m: .nan\n").find("must be finite"), std::string::npos);
  EXPECT_NE(ErrorFor("scenario:\n  ranging:\n    outlier_probability: 1.5\n").find("outlier_probability"),
            std::string::npos);
  EXPECT_NE(ErrorFor("scenario:\n  trajectory:\n    kind: spiral\n").find("unknown value 'spiral' (choices: random"),
            std::string::npos);
}

// The options structs check their own limits (IsValid); the config reader names the key they
// are about, with its value, or the section where no single key is to blame.
TEST(Config, CrossFieldChecksNameTheKeyOrTheSection) {
  std::string error = ErrorFor("scenario:\n  tunnel:\n    anchor_height_min_m: 4\n    anchor_height_max_m: 2\n");
  EXPECT_NE(error.find("key 'scenario.tunnel.anchor_height_max_m': must be in [anchor_height_min_m, height_m], got '2'"),
            std::string::npos)
      << error;
  error = ErrorFor("scenario:\n  trajectory: {fraction_straight: 0.6, fraction_planar: 0.6}\n");
  EXPECT_NE(error.find("key 'scenario.trajectory': fraction_straight, fraction_planar and fraction_short must sum to <= 1"),
            std::string::npos)
      << error;
  // Bursts of mean length 1 cannot make more than half of the ranges outliers.
  error = ErrorFor("scenario:\n  ranging: {outlier_probability: 0.99, outlier_burst_length: 1}\n");
  EXPECT_NE(error.find("key 'scenario.ranging.outlier_probability': must be <= L/(L+1)"), std::string::npos) << error;
  error = ErrorFor("estimator:\n  height_prior: {enabled: true, sigma_m: 0}\n");
  EXPECT_NE(error.find("key 'estimator.height_prior.sigma_m': must be in (0, 1e4]"), std::string::npos) << error;
  EXPECT_EQ(ErrorFor("estimator:\n  height_prior: {enabled: true, sigma_m: 0.2, from_reference: true, offset_m: -1}\n"
                     "  trigger: {horizontal_threshold: 0.8}\n  triggers: [hdop_closest_point]\n"),
            "");
  error = ErrorFor("estimator:\n  filter: {ransac: {scheme: full_solve, subset_size: 200, outlier_fraction: 0.99}}\n");
  EXPECT_NE(error.find("key 'estimator.filter.ransac.subset_size'"), std::string::npos) << error;
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
  EXPECT_NE(error_for("scenario.tunnel.width_m=-3").find("must be in (0, 1e5]"), std::string::npos);
  EXPECT_NE(error_for("scenario.tunnel").find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(error_for("scenario.tunnel.width_m.x=1").find("'width_m' is not a section"), std::string::npos);
  EXPECT_NE(error_for("seed.x=1").find("key 'seed': expected a whole number"), std::string::npos);
  EXPECT_EQ(error_for("scenario.tunnel.width_m="), "--set 'scenario.tunnel.width_m=': no value (KEY=VALUE, e.g. width_m=1)");
  EXPECT_NE(error_for("scenario.tunnel.width_m=~").find("no value"), std::string::npos);
  EXPECT_NE(error_for("seed=1\n---\n2").find("a second YAML document"), std::string::npos);

  const std::string table = dir.Write("rows.yaml", "rows:\n  - name: a\n  - name: b\n");
  const ExperimentConfig rows = LoadConfig(table, {"rows.1.scenario.ranging.sigma_range_m=0.3"});
  EXPECT_EQ(rows.rows[0].scenario.ranging.sigma_range_m, 0.1);
  EXPECT_EQ(rows.rows[1].scenario.ranging.sigma_range_m, 0.3);
  EXPECT_THROW(LoadConfig(table, {"rows.2.scenario.ranging.sigma_range_m=0.3"}), InputError);
}

TEST(Config, SolverByRegistryName) {
  testing::TempDir dir("solver");
  EXPECT_EQ(LoadConfig(dir.Write("a.yaml", "estimator: {solver: nlopt:LN_BOBYQA}\n")).estimator.solver,
            "nlopt:LN_BOBYQA");
  EXPECT_NE(ErrorFor("estimator: {solver: lm_magic}\n").find("key 'estimator.solver': unknown solver 'lm_magic'"),
            std::string::npos);
  EXPECT_NE(ErrorFor("estimator: {solver: 'nlopt:GN_CRS2_LM'}\n").find("draws from NLopt's process-wide random generator"),
            std::string::npos);
}

// A part registered by the caller can be named in a file; one the caller did not register cannot.
TEST(Config, NamesAreValidatedAgainstTheCallersRegistry) {
  testing::TempDir dir("own_solver");
  const std::string path = dir.Write("own.yaml", "estimator: {solver: my_solver}\n");
  EXPECT_THROW(LoadConfig(path), InputError);
  registry::Components mine = eval::MakeComponentsWithOracles();
  mine.solvers.Register("my_solver", "mine", [](const std::string&, const registry::SolverContext& context) {
    return std::make_unique<estimator::AnchorSolver>(context.options);
  });
  EXPECT_EQ(config::LoadConfig(path, {}, mine).estimator.solver, "my_solver");
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
  EXPECT_EQ(again.estimator.solver_options.nls.kernel, config.estimator.solver_options.nls.kernel);
}

TEST(ConfigFiles, BaseInheritanceOnlyRowsAndOverridesThatReachRows) {
  testing::TempDir dir("base");
  dir.Write("table.yaml",
            "scenario:\n  tunnel: {width_m: 10}\nestimator:\n  filter: {tau_m: 0.2}\n"
            "rows:\n  - {name: a, estimator: {filter: {tau_m: 0.3}}}\n  - {name: b}\n");
  const std::string derived = dir.Write("derived.yaml",
                                        "base: table.yaml\nrealizations: 7\nonly_rows: [b]\n"
                                        "scenario:\n  tunnel: {height_m: 7}\nsweep:\n  estimator.filter.tau_m: 0.1:0.3:0.1\n");
  const ExperimentConfig config = LoadConfig(derived);
  EXPECT_EQ(config.realizations, 7);
  EXPECT_EQ(config.scenario.tunnel.width_m, 10.0);  // from the base file
  EXPECT_EQ(config.scenario.tunnel.height_m, 7.0);  // merged over it
  ASSERT_EQ(RowsOf(config).size(), 1u);
  EXPECT_EQ(RowsOf(config)[0].name, "b");
  ASSERT_EQ(config.sweep.size(), 1u);
  EXPECT_EQ(config.sweep[0].second, "0.1:0.3:0.1");

  // An override of a base key also replaces the rows' own values of it.
  const ExperimentConfig swept = LoadConfig(derived, {"estimator.filter.tau_m=0.9"});
  EXPECT_EQ(swept.estimator.filter.consistency.tau_m, 0.9);
  EXPECT_EQ(swept.rows[0].estimator.filter.consistency.tau_m, 0.9);  // row a had its own 0.3
  EXPECT_EQ(swept.rows[1].estimator.filter.consistency.tau_m, 0.9);

  const std::string unknown_row = dir.Write("bad.yaml", "base: table.yaml\nonly_rows: [c]\n");
  EXPECT_THROW(LoadConfig(unknown_row), InputError);
  const std::string cycle = dir.Write("cycle.yaml", "base: cycle.yaml\n");
  EXPECT_THROW(LoadConfig(cycle), InputError);
}

// The shipped Table I calibration: scenario keys only, each with bounds around the configured
// value, verified on at least five seeds the fit does not use.
TEST(Calibration, ShippedCalibrationLoadsAndBracketsTheConfiguredScenario) {
  const schema::CalibrationSpec spec = LoadCalibrationSpec(std::string(ANCHORBENCH_CONFIG_DIR) + "/calibrate_table1.yaml");
  EXPECT_EQ(std::filesystem::path(spec.experiment_path).filename(), "table1.yaml");
  const std::string resolved = ToYaml(LoadConfig(spec.experiment_path));
  for (const schema::FreeParameter& p : spec.parameters) {
    EXPECT_EQ(p.key.rfind("scenario.", 0), 0u) << p.key;
    const double configured = NumberAt(resolved, p.key, "test");
    EXPECT_LE(p.min, configured) << p.key;
    EXPECT_GE(p.max, configured) << p.key;
  }
  EXPECT_GE(spec.verify_seeds.size(), 5u);
  EXPECT_EQ(std::count(spec.verify_seeds.begin(), spec.verify_seeds.end(), spec.seed), 0);
  EXPECT_GT(spec.fit_weight.avg_m, 0.0);
  EXPECT_EQ(spec.fit_weight.ratio_pct, 0.0);  // held out: predicted, not fitted
}

TEST(Calibration, ErrorsNameTheKey) {
  testing::TempDir dir("calibration");
  auto error_for = [&](const std::string& yaml) -> std::string {
    try {
      LoadCalibrationSpec(dir.Write("c.yaml", yaml));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string parameter = "parameters: [{key: scenario.tunnel.width_m, min: 6, max: 24, provenance: x}]\n";
  EXPECT_EQ(error_for("experiment: e.yaml\n" + parameter), "");
  EXPECT_NE(error_for(parameter).find("'experiment' is missing"), std::string::npos);
  EXPECT_NE(error_for("experiment: e.yaml\nparameters: [{key: scenario.a, min: 2, max: 1, provenance: x}]\n")
                .find("key 'parameters[0].max': must be greater than min"),
            std::string::npos);
  EXPECT_NE(error_for("experiment: e.yaml\nfit: {avg_m: 0, med_m: 0, init: 0}\n" + parameter).find("nothing to fit"),
            std::string::npos);
  EXPECT_NE(error_for("experiment: e.yaml\nlocal: {algorithm: LD_LBFGS}\n" + parameter).find("no gradient"),
            std::string::npos);
  EXPECT_NE(error_for("experiment: e.yaml\nverify_seeds: [2, x]\n" + parameter).find("'x' is not a seed"),
            std::string::npos);
  EXPECT_NE(error_for("experiment: e.yaml\nbogus: 1\n" + parameter).find("bogus"), std::string::npos);
}

}  // namespace
}  // namespace anchorbench::config

namespace anchorbench::config {
namespace {

// Every seed the command line takes (0 to 2^63-1) is written and read back exactly: the resolved
// config of a manifest, a shard folder and a worker rank's plan are made from this text.
TEST(Config, SeedsRoundTripExactly) {
  for (const std::uint64_t seed : {0ull, 2147483648ull, 4294967301ull, 9223372036854775807ull}) {
    ExperimentConfig config;
    config.seed = seed;
    const std::string yaml = ToYaml(config);
    EXPECT_NE(yaml.find("seed: " + std::to_string(seed) + "\n"), std::string::npos) << yaml.substr(0, 40);
    EXPECT_EQ(LoadConfigText(yaml, "t.yaml", {}, testing::AllComponents()).seed, seed);
    EXPECT_EQ(ToJson(config)["seed"].get<std::uint64_t>(), seed);
  }
  EXPECT_THROW(LoadConfigText("seed: 9223372036854775808\n", "t.yaml", {}, testing::AllComponents()), InputError);
  EXPECT_THROW(LoadConfigText("seed: -1\n", "t.yaml", {}, testing::AllComponents()), InputError);
}

std::string Refusal(const std::string& text) {
  try {
    LoadConfigText(text, "t.yaml", {}, testing::AllComponents());
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// What a file says is what runs: a second document, a key without a value, a row name that would
// break a CSV line, and an alias bomb are refused with the place.
TEST(Config, RefusesWhatWouldBeIgnoredOrMisread) {
  EXPECT_EQ(Refusal("seed: 1\n---\nseed: 2\n"), "t.yaml:3: a second YAML document (after '---'): a config is one document");
  // yaml-cpp's parser stalls on a ',' outside a flow collection and hands out empty documents
  // without end (fuzz_config found it as a timeout); before, the first, empty one ran as the config.
  EXPECT_NE(Refusal(",seed: 3\nrows: {b: :0.1\n").find("t.yaml:1: YAML syntax error: the reader cannot go past"),
            std::string::npos);
  EXPECT_EQ(Refusal("---\n"), "accepted");
  EXPECT_EQ(Refusal("sweep: ~\n"), "t.yaml: key 'sweep': no value (give one, or remove the key to keep the default)");
  EXPECT_EQ(Refusal("sigma: ~\n"), "t.yaml: key 'sigma': unknown key");
  // A section without a value is refused as a number without one is, never a silent reset.
  EXPECT_EQ(Refusal("scenario: ~\n"), "t.yaml: key 'scenario': no value (give one, or remove the key to keep the default)");
  EXPECT_EQ(Refusal("estimator: {filter: ~}\n"),
            "t.yaml: key 'estimator.filter': no value (give one, or remove the key to keep the default)");
  EXPECT_NE(Refusal("rows:\n  - name: a\n  - name: b\n  - name: a\n").find("rows 0 and 2 are both named 'a'"),
            std::string::npos);
  EXPECT_NE(Refusal("rows:\n  - name: \"a,b\"\n").find("key 'rows[0].name': 'a,b' holds ','"), std::string::npos);
  EXPECT_NE(Refusal("rows:\n  - name: \"b\\nc\"\n").find("key 'rows[0].name': 'b\\x0Ac' holds"), std::string::npos);
  EXPECT_NE(Refusal("experiment: e.yaml\n").find("is a calibration file"), std::string::npos);
  EXPECT_NE(Refusal("scenario: {tunnel: {width_m: 1e308}}\n").find("must be a finite number of magnitude at most 1e+300"),
            std::string::npos);
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i <= 10; ++i) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
    bomb.append("a").append(std::to_string(i)).append(": &a").append(std::to_string(i)).append(" [");
    for (int k = 0; k < 9; ++k) bomb.append(k ? ", " : "").append("*a").append(std::to_string(i - 1));
    bomb += "]\n";
  }
  EXPECT_NE(Refusal(bomb).find("expands to more than 200000 values"), std::string::npos);
}

// Every file a config reads: a command never overwrites or deletes one of them.
// The initializer's keys left `trigger` for `initializer`: an old file, row or override is refused
// with the key's new place, never read into the wrong struct or ignored.
TEST(Config, AKeyThatMovedNamesItsNewPlace) {
  for (const char* key : {"min_samples", "retry_growth", "max_buffered_samples", "at_cap"}) {
    try {
      LoadConfigText(std::string("estimator:\n  trigger:\n    ") + key + ": 30\n", "old.yaml", {}, AllComponents());
      ADD_FAILURE() << key << " under trigger was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), std::string("old.yaml: key 'estimator.trigger.") + key +
                                           "': has moved: write it as estimator.initializer." + key);
    }
  }
  try {
    LoadConfigText("rows:\n  - name: a\n    estimator: {trigger: {min_samples: 5}}\n", "row.yaml", {}, AllComponents());
    ADD_FAILURE() << "a row's old key was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("write it as rows[0].estimator.initializer.min_samples"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(LoadConfigText("seed: 1\n", "o.yaml", {"estimator.trigger.min_samples=5"}, AllComponents()), InputError);
  EXPECT_EQ(LoadConfigText("seed: 1\n", "n.yaml", {"estimator.initializer.min_samples=25"}, AllComponents())
                .estimator.initializer.min_samples,
            25);
}

TEST(Config, ConfigFilesListsTheBaseChain) {
  anchorbench::testing::TempDir dir("files");
  dir.Write("a.yaml", "seed: 1\n");
  dir.Write("b.yaml", "base: a.yaml\n");
  const std::string c = dir.Write("c.yaml", "base: b.yaml\n");
  const std::vector<std::string> files = ConfigFiles(c);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0], c);
  EXPECT_EQ(std::filesystem::path(files[2]).filename(), "a.yaml");
}

}  // namespace
}  // namespace anchorbench::config
