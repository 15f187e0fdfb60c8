#include "anchorbench/config/load_calibration.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/config/yaml_section.hpp"
#include "anchorbench/estimator/nlopt_solver.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::config {
namespace {

void Stage(YamlSection& s, schema::OptimizerStage& stage) {
  s.Text("algorithm", stage.algorithm);
  s.Integer("max_evaluations", stage.max_evaluations, 0, 100000);
  std::string why;
  if (estimator::NloptSolver::AlgorithmNumber(stage.algorithm) < 0) {
    s.Fail("algorithm", "unknown algorithm '" + stage.algorithm +
                            "' (NLopt's names, derivative-free: e.g. GN_DIRECT_L, GN_ESCH, LN_SBPLX, LN_NELDERMEAD, LN_BOBYQA)");
  }
  const bool derivative_free = stage.algorithm.rfind("GN_", 0) == 0 || stage.algorithm.rfind("LN_", 0) == 0;
  if (!derivative_free) {
    s.Fail("algorithm", "'" + stage.algorithm + "': the objective has no gradient; choose a GN_* or LN_* algorithm");
  }
  if (!estimator::NloptSolver::Accepts(stage.algorithm, &why)) s.Fail("algorithm", why);
}

void Parameter(YamlSection& s, schema::FreeParameter& p) {
  s.Text("key", p.key);
  s.Number("min", p.min);
  s.Number("max", p.max);
  s.Text("provenance", p.provenance);
  // Only the simulation is fitted: the estimator keeps the paper's rules. Keys inside `rows`
  // would need the calibrated config to rewrite the rows list (not supported yet).
  if (p.key.rfind("scenario.", 0) != 0) {
    s.Fail("key", "'" + p.key + "': only keys under 'scenario' can be calibrated (the estimator is never fitted)");
  }
  if (!(p.min < p.max)) s.Fail("max", "must be greater than min");
  if (p.provenance.empty()) s.Fail("provenance", "say where the range comes from (what the paper states, or 'not stated')");
}

std::vector<std::uint64_t> Seeds(YamlSection& s, std::string_view key, std::vector<std::uint64_t> seeds) {
  if (!s.Has(key)) return seeds;
  std::vector<std::string> texts;
  s.TextList(key, texts);
  seeds.clear();
  for (const std::string& text : texts) {
    std::uint64_t seed = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seed);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || seed > schema::kMaxSeed) {
      s.Fail(key, "'" + text + "' is not a seed (a whole number from 0 to " + std::to_string(schema::kMaxSeed) + ")");
    }
    if (std::find(seeds.begin(), seeds.end(), seed) != seeds.end()) s.Fail(key, "seed " + text + " is listed twice");
    seeds.push_back(seed);
  }
  if (seeds.empty()) s.Fail(key, "expected at least one seed");
  return seeds;
}

}  // namespace

schema::CalibrationSpec LoadCalibrationSpec(const std::string& path) {
  const YAML::Node root = LoadConfigYaml(path, {});
  schema::CalibrationSpec spec;
  spec.path = path;
  YamlSection top(root, "", path);
  if (!top.Has("experiment")) top.FailSection("'experiment' is missing: the experiment file to calibrate");
  top.Text("experiment", spec.experiment_path);
  spec.experiment_path = (std::filesystem::path(path).parent_path() / spec.experiment_path).lexically_normal().string();
  top.Unsigned("seed", spec.seed, schema::kMaxSeed);
  top.Integer("realizations", spec.realizations, 1, 100000000);
  spec.verify_seeds = Seeds(top, "verify_seeds", spec.verify_seeds);
  if (std::find(spec.verify_seeds.begin(), spec.verify_seeds.end(), spec.seed) != spec.verify_seeds.end()) {
    top.Fail("verify_seeds", "holds the fit's seed " + std::to_string(spec.seed) + ": verification needs unseen seeds");
  }
  top.Section("fit", [&](YamlSection& s) {
    constexpr Bounds kWeight{0.0};
    s.Number("avg_m", spec.fit_weight.avg_m, kWeight);
    s.Number("med_m", spec.fit_weight.med_m, kWeight);
    s.Number("init", spec.fit_weight.init, kWeight);
    s.Number("gt1m", spec.fit_weight.gt1m, kWeight);
    s.Number("ratio_pct", spec.fit_weight.ratio_pct, kWeight);
    const schema::PaperCells& w = spec.fit_weight;
    if (w.avg_m + w.med_m + w.init + w.gt1m + w.ratio_pct <= 0.0) s.FailSection("every weight is 0: nothing to fit");
  });
  top.Number("band", spec.band, {0.0, 0.9});
  top.Section("global", [&](YamlSection& s) { Stage(s, spec.global); });
  top.Section("local", [&](YamlSection& s) { Stage(s, spec.local); });
  top.Number("profile_step", spec.profile_step, {0.0, 0.4, true});
  if (!top.Has("parameters")) top.FailSection("'parameters' is missing: the scenario keys to fit, with bounds");
  top.List("parameters", spec.parameters, [] { return schema::FreeParameter{}; }, Parameter);
  if (spec.parameters.empty()) top.Fail("parameters", "expected at least one parameter");
  for (std::size_t i = 0; i < spec.parameters.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (spec.parameters[i].key == spec.parameters[j].key) {
        top.Fail("parameters", "'" + spec.parameters[i].key + "' is listed twice");
      }
    }
  }
  top.Finish();
  return spec;
}

double NumberAt(const std::string& resolved_yaml, const std::string& key, const std::string& what) {
  YAML::Node node = YAML::Load(resolved_yaml);
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!node.IsMap() || !node[part]) throw schema::InputError(what + ": '" + key + "' is not a key of the experiment");
    node.reset(node[part]);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value)) {
    throw schema::InputError(what + ": '" + key + "' is not a number in the experiment");
  }
  return value;
}

}  // namespace anchorbench::config
