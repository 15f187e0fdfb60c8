// The trials from Python: configs, run, sweep, navigate, explore, pdop_study, replay and simulate, each returning the files the
// command line writes (the same bytes), which the package reads into DataFrames and can save.
#include <filesystem>
#include <map>
#include <sstream>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/engine/commit.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/run_plan.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/log_policy.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/io/scenario_files.hpp"
#include "anchorbench/report/replay_report.hpp"
#include "anchorbench/report/replay_summary.hpp"
#include "anchorbench/report/why_not.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/schema/sweep.hpp"
#include "anchorbench/sim/scenario.hpp"
#include "anchorbench/studies/exploration.hpp"
#include "anchorbench/studies/navigation.hpp"
#include "anchorbench/studies/navigation_log.hpp"
#include "anchorbench/studies/pdop_study.hpp"
#include "anchorbench/studies/replay_log.hpp"
#include "config_handle.hpp"
#include "interruptible.hpp"
#include "module_parts.hpp"

namespace anchorbench::app {
const char* BuildRevision();  // generated at build time (cmake/GitRevision.cmake)
}

namespace anchorbench::python {

ConfigHandle LoadConfigFile(const std::string& path, const std::vector<std::string>& overrides) {
  ConfigHandle handle{config::ReadConfigDocument(path), {}, path, overrides, config::ConfigFiles(path)};
  handle.experiment = config::LoadConfig(handle.document, overrides, ModuleComponents());
  return handle;
}

ConfigHandle LoadConfigText(const std::string& text, const std::string& source, const std::vector<std::string>& overrides) {
  ConfigHandle handle{config::ParseConfigDocument(text, source), {}, source, overrides, {}};
  handle.experiment = config::LoadConfig(handle.document, overrides, ModuleComponents());
  // A dict's `base:` (relative to the working folder) and the files it chains to.
  if (const YAML::Node base = YAML::Load(text)["base"]; base && base.IsScalar()) {
    const std::filesystem::path parent = std::filesystem::path(source).parent_path();
    handle.files = config::ConfigFiles((parent / base.Scalar()).string());
  }
  return handle;
}

namespace {

// A result's files by name, in the order the command writes them, and the files it was made from
// (which save() never replaces).
struct Files {
  std::vector<std::pair<std::string, std::string>> texts;
  std::vector<std::filesystem::path> inputs;
  std::string notes;  // what the command line prints on stderr beside the files (replay's drops)

  engine::FileWriter Writer() {
    return [this](const std::string& name, const std::function<void(std::ostream&)>& write) {
      std::ostringstream text;
      write(text);
      texts.emplace_back(name, text.str());
    };
  }
  std::vector<std::string> Names() const {
    std::vector<std::string> names;
    for (const auto& [name, text] : texts) names.push_back(name);
    return names;
  }
  const std::string& Text(const std::string& name) const {
    for (const auto& [file, text] : texts) {
      if (file == name) return text;
    }
    throw py::key_error(name);
  }
  // Whole or absent, as the command line's result folders (io::ResultFolder).
  void Save(const std::filesystem::path& folder, bool overwrite) const {
    if (folder.empty()) throw schema::InputError("folder: an empty path; name the folder to write");
    io::ResultFolder::Options options;
    options.overwrite = overwrite;
    options.inputs = inputs;
    options.overwrite_option = "overwrite=True";
    io::ResultFolder out(folder, options);
    for (const auto& [name, text] : texts) out.Write(name, text);
    out.Commit();
  }
};

report::RunInfo InfoOf(const ConfigHandle& config, int threads, std::vector<std::string> command_line) {
  report::RunInfo info;
  info.config_path = config.source;
  info.revision = app::BuildRevision();
  info.threads = threads;
  info.command_line = std::move(command_line);
  info.command_line.insert(info.command_line.begin(), "python");
  info.resolved_config = config::ToJson(config.experiment);
  return info;
}

// The plan on this process's threads, the GIL released (a Python part takes it back while it
// runs), Ctrl-C and `progress` heard (interruptible.hpp).
std::vector<engine::ExperimentAttempts> Compute(const engine::Plan& plan, int threads, const py::object& progress) {
  return Interruptible<std::vector<engine::ExperimentAttempts>>(
      [&](const engine::RunControl& control) {
        engine::LocalExecutor executor(ModuleComponents(), control.stop);
        return engine::RunWholePlan(plan, executor, threads, control.progress);
      },
      progress);
}

Files Run(const ConfigHandle& config, int threads, const py::object& progress) {
  engine::CheckExperiment(config.experiment, ModuleComponents());
  const int resolved = engine::ResolveThreads(threads);
  const engine::Plan plan({config.experiment});
  const std::vector<engine::ExperimentAttempts> run = Compute(plan, resolved, progress);
  Files files{{}, {config.files.begin(), config.files.end()}, {}};
  engine::WriteRunFiles(files.Writer(), config.experiment, run.front(), InfoOf(config, resolved, {"run"}));
  return files;
}

Files Sweep(const ConfigHandle& config, const std::vector<std::string>& axes_text, int threads,
            const py::object& progress) {
  const std::vector<schema::SweepAxis> axes = schema::SweepAxes(config.experiment.sweep, axes_text);
  if (axes.empty()) throw schema::InputError(config.source + ": nothing to sweep: give axes or a 'sweep' section");
  const std::vector<schema::ExperimentConfig> points =
      engine::SweepPoints(config.document, config.overrides, axes, std::nullopt, ModuleComponents());
  const int resolved = engine::ResolveThreads(threads);
  const engine::Plan plan(points);
  const std::vector<engine::ExperimentAttempts> run = Compute(plan, resolved, progress);
  Files files{{}, {config.files.begin(), config.files.end()}, {}};
  engine::WriteSweepFiles(files.Writer(), config.experiment.name, axes, plan, run, InfoOf(config, resolved, {"sweep"}));
  return files;
}

Files Navigate(const ConfigHandle& config, int threads, const py::object& progress) {
  studies::CheckNavigation(config.experiment, ModuleComponents());
  const int resolved = engine::ResolveThreads(threads);
  const std::vector<studies::NavigationRecord> records = Interruptible<std::vector<studies::NavigationRecord>>(
      [&](const engine::RunControl& control) {
        return studies::RunNavigation(config.experiment, ModuleComponents(), resolved, {}, control);
      },
      progress);
  Files files{{}, {config.files.begin(), config.files.end()}, {}};
  studies::WriteNavigationFiles(files.Writer(), config.experiment, records, InfoOf(config, resolved, {"navigate"}));
  return files;
}

Files Explore(const ConfigHandle& config, int threads, const py::object& progress) {
  studies::CheckExploration(config.experiment, ModuleComponents());
  const int resolved = engine::ResolveThreads(threads);
  const std::vector<studies::ExplorationRecord> records = Interruptible<std::vector<studies::ExplorationRecord>>(
      [&](const engine::RunControl& control) {
        return studies::RunExploration(config.experiment, ModuleComponents(), resolved, control);
      },
      progress);
  Files files{{}, {config.files.begin(), config.files.end()}, {}};
  studies::WriteExplorationFiles(files.Writer(), config.experiment, records, InfoOf(config, resolved, {"explore"}));
  return files;
}

Files PdopStudy(const ConfigHandle& config, int threads, const py::object& progress) {
  studies::CheckPdopStudy(config.experiment, ModuleComponents());
  const int resolved = engine::ResolveThreads(threads);
  const std::vector<schema::PdopStudy> realizations = Interruptible<std::vector<schema::PdopStudy>>(
      [&](const engine::RunControl& control) {
        return studies::RunPdopStudy(config.experiment, ModuleComponents(), resolved, control);
      },
      progress);
  Files files{{}, {config.files.begin(), config.files.end()}, {}};
  studies::WritePdopStudyFiles(files.Writer(), config.experiment, realizations,
                               InfoOf(config, resolved, {"pdop-study"}));
  return files;
}

// What replay reads besides the files: the CLI's options (replay --help), and which traces to keep.
struct ReplayRequest {
  io::LogPolicy policy;
  std::string repeated_poses = "error", out_of_order = "sort";
  bool navigate = false, trace = false, certificate_trace = false;
};

// replay's outputs as the CLI writes them into --out, plus the traces asked for (trace.csv,
// certificate_trace.csv) and the drop summary the CLI prints (Files::notes).
Files Replay(const std::string& poses, const std::vector<std::string>& ranges, const std::string& anchors,
             const ConfigHandle* config, ReplayRequest request) {
  const schema::ExperimentConfig experiment = config ? config->experiment : schema::ExperimentConfig{};
  if (request.navigate) studies::CheckLogNavigation(experiment);
  request.policy.repeated_poses = io::RepeatedPosesFromName(request.repeated_poses);
  request.policy.out_of_order = io::OutOfOrderFromName(request.out_of_order);
  std::optional<std::map<int, schema::AnchorTruth>> truth;
  if (!anchors.empty()) truth = io::LoadAnchors(anchors);
  Files files;
  files.inputs = {poses};
  files.inputs.insert(files.inputs.end(), ranges.begin(), ranges.end());
  if (!anchors.empty()) files.inputs.emplace_back(anchors);
  if (config) files.inputs.insert(files.inputs.end(), config->files.begin(), config->files.end());
  py::gil_scoped_release release;
  const studies::ReplayLog replay({poses, ranges}, request.policy, std::move(truth), experiment, ModuleComponents());
  if (request.navigate) {
    studies::CheckErrorBins(replay.survey().t_last_pose_s - replay.survey().t_first_pose_s, *experiment.navigation, poses);
  }
  std::ostringstream trace_text, certificate_text;
  studies::TraceSink trace;
  if (request.trace) {
    trace_text << report::kTraceHeader << '\n';
    trace = [&](const io::RangeRecord& r, const estimator::FeedResult& fed) { report::WriteTraceRow(trace_text, r, fed); };
  }
  studies::JudgementSink judged;
  if (request.certificate_trace) {
    certificate_text << report::kJudgementColumns << '\n';
    judged = [&](int anchor_id, std::size_t trigger, const estimator::Judgement& judgement) {
      report::WriteJudgementRow(certificate_text, anchor_id, experiment.estimator.triggers[trigger], judgement);
    };
  }
  const studies::ReplayOutcome outcome = replay.Run(trace, {}, judged);
  studies::WriteReplayFiles(files.Writer(), outcome);  // into C++ strings: no Python object touched
  if (request.navigate) studies::WriteLogNavigation(files.Writer(), replay, outcome, experiment, engine::ResolveThreads(0));
  if (request.trace) files.texts.emplace_back("trace.csv", trace_text.str());
  if (request.certificate_trace) files.texts.emplace_back("certificate_trace.csv", certificate_text.str());
  std::ostringstream notes;
  if (outcome.summary.drops.total() > 0 || outcome.summary.reordered_rows > 0) report::PrintReplaySummary(notes, outcome.summary);
  files.notes = notes.str();
  return files;
}

Files Simulate(const ConfigHandle& config, std::uint64_t realization) {
  const sim::Scenario scenario = sim::GenerateScenario(config.experiment.scenario, config.experiment.seed, realization);
  const io::Recording recording = io::RecordingOf(scenario);
  Files files{{}, {config.files.begin(), config.files.end()}, {}};
  engine::FileWriter write = files.Writer();
  write("poses.csv", [&](std::ostream& out) { io::WritePoses(out, recording.poses); });
  write("ranges.csv", [&](std::ostream& out) { io::WriteRanges(out, recording.ranges); });
  write("anchors.csv", [&](std::ostream& out) { io::WriteAnchors(out, recording.anchors); });
  return files;
}

}  // namespace

void BindTrials(py::module_& m) {
  py::class_<ConfigHandle>(m, "Config", "An experiment config, resolved (bases and overrides applied) and validated.")
      .def_property_readonly("name", [](const ConfigHandle& c) { return c.experiment.name; })
      .def_property_readonly("source", [](const ConfigHandle& c) { return c.source; })
      .def_property_readonly("seed", [](const ConfigHandle& c) { return c.experiment.seed; })
      .def_property_readonly("realizations", [](const ConfigHandle& c) { return c.experiment.realizations; })
      .def_property_readonly("triggers", [](const ConfigHandle& c) { return c.experiment.estimator.triggers; })
      .def_property_readonly("yaml", [](const ConfigHandle& c) { return config::ToYaml(c.experiment); },
                             "the resolved config in the file schema");
  m.def("_load_config_file", &LoadConfigFile, py::arg("path"), py::arg("overrides"));
  m.def("_load_config_text", &LoadConfigText, py::arg("text"), py::arg("source"), py::arg("overrides"));
  py::class_<Files>(m, "Files", "A result's files, as the command line writes them.")
      .def_property_readonly("names", &Files::Names)
      .def_property_readonly("notes", [](const Files& f) { return f.notes; })
      .def(
          "_rename_input",
          [](Files& f, const std::string& path, const std::string& name) {  // a temporary file, as the user knows it
            const auto rename = [&](std::string& text) {
              for (std::size_t at = text.find(path); at != std::string::npos; at = text.find(path, at + name.size())) {
                text.replace(at, path.size(), name);
              }
            };
            rename(f.notes);
            for (auto& [file, text] : f.texts) rename(text);
          },
          py::arg("path"), py::arg("name"))
      .def("text", &Files::Text, py::arg("name"))
      .def("save", &Files::Save, py::arg("folder"), py::arg("overwrite") = false,
           "Writes the files into `folder`, whole or not at all; an existing folder only with overwrite=True.");
  m.def("_run", &Run, py::arg("config"), py::arg("threads"), py::arg("progress"));
  m.def("_sweep", &Sweep, py::arg("config"), py::arg("axes"), py::arg("threads"), py::arg("progress"));
  m.def("_navigate", &Navigate, py::arg("config"), py::arg("threads"), py::arg("progress"));
  m.def("_explore", &Explore, py::arg("config"), py::arg("threads"), py::arg("progress"));
  m.def("_pdop_study", &PdopStudy, py::arg("config"), py::arg("threads"), py::arg("progress"));
  m.def(
      "_replay",
      [](const std::string& poses, const std::vector<std::string>& ranges, const std::string& anchors,
         const ConfigHandle* config, const std::string& repeated_poses, const std::string& out_of_order, bool navigate,
         double max_range_m, double average_poses_within_m, double sort_window_s, double max_speed_mps, bool strict,
         bool trace, bool certificate_trace) {
        ReplayRequest request;
        request.repeated_poses = repeated_poses;
        request.out_of_order = out_of_order;
        request.navigate = navigate;
        request.policy.max_range_m = max_range_m;
        request.policy.average_within_m = average_poses_within_m;
        request.policy.sort_window_s = sort_window_s;
        request.policy.max_speed_mps = max_speed_mps;
        request.policy.strict = strict;
        request.trace = trace;
        request.certificate_trace = certificate_trace;
        return Replay(poses, ranges, anchors, config, std::move(request));
      },
      py::arg("poses"), py::arg("ranges"), py::arg("anchors"), py::arg("config"), py::arg("repeated_poses"),
      py::arg("out_of_order"), py::arg("navigate"), py::arg("max_range_m"), py::arg("average_poses_within_m"),
      py::arg("sort_window_s"), py::arg("max_speed_mps"), py::arg("strict"), py::arg("trace"),
      py::arg("certificate_trace"));
  m.def("_simulate", &Simulate, py::arg("config"), py::arg("realization"));
}

}  // namespace anchorbench::python
