// anchorbench: Monte Carlo simulation and benchmarking of online UWB anchor initialization.
// The only file that sees CLI11: it maps the command line onto the commands of commands.hpp.
#include <malloc.h>

#include <charconv>
#include <iostream>
#include <limits>
#include <string>

#include <CLI/CLI.hpp>

#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/example_parts/example_parts.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "commands.hpp"
#include "interrupt.hpp"
#ifdef ANCHORBENCH_MPI
#include "mpi_job.hpp"
#endif

namespace app = anchorbench::app;

namespace anchorbench::app {
const char* BuildRevision();  // generated at build time (cmake/GitRevision.cmake)
}  // namespace anchorbench::app

namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 done; 2 bad input or usage (one message naming the file and line, the config key or the "
    "option; nothing written); 3 internal error.";

// A whole number in [min, max], checked on the text: CLI11 would wrap "-1" into an unsigned
// option and word its own range errors in doubles.
CLI::Validator WholeNumber(long long min, long long max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (text.empty() || ec != std::errc() || ptr != end || value < min || value > max) {
          return "expected a whole number from " + std::to_string(min) + " to " + std::to_string(max) + ", got '" +
                 text + "'";
        }
        return "";
      },
      "INT");
}

// A number in [min, max], checked on the text: CLI::Range lets "nan" through (every comparison
// with it is false), and "inf" must not stand for "no limit".
CLI::Validator FiniteNumber(double min, double max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        double value = 0.0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (text.empty() || ec != std::errc() || ptr != end || !(value >= min && value <= max)) {
          return "expected a finite number from " + anchorbench::io::FormatNumber(min) + " to " +
                 anchorbench::io::FormatNumber(max) + ", got '" + text + "'";
        }
        return "";
      },
      "NUMBER");
}

// The options every Monte Carlo command shares (run, sweep, pdop-study; calibrate without
// --realizations).
void AddMonteCarloOptions(CLI::App* cmd, app::MonteCarloArgs& args, bool realizations = true) {
  cmd->add_option("--out", args.out, "Output folder (default results/<config name>/), replaced as a whole");
  cmd->add_option("--threads", args.threads, "OpenMP threads (default: OMP_NUM_THREADS, else all cores)")
      ->check(WholeNumber(0, 1 << 20));
  if (realizations) {
    cmd->add_option("--realizations", args.realizations, "Override the realizations per row")
        ->check(WholeNumber(1, 100000000));
  }
  cmd->add_flag("--quiet", args.quiet, "No progress output");
  cmd->add_flag("--overwrite", args.overwrite, "Replace an output folder that holds earlier results");
}

// run and sweep: finished chunks kept in <out>.chunks/ until the results are written, and shards.
void AddChunkOptions(CLI::App* cmd, app::MonteCarloArgs& args) {
  cmd->add_flag("--resume", args.resume,
                "Continue an interrupted run from <out>.chunks/ (its finished chunks are kept); the results are "
                "byte-identical to an uninterrupted run's");
  cmd->add_option("--shard", args.shard,
                  "I/N: compute only shard I of N of the chunks into a shard folder; `anchorbench merge` joins the N "
                  "folders (docs/cluster.md)");
}

// navigate, explore and pdop-study: finished (row, realization) units kept in <out>.chunks/ until the results
// are written, and shards of them.
void AddUnitOptions(CLI::App* cmd, app::MonteCarloArgs& args) {
  cmd->add_flag("--resume", args.resume,
                "Continue an interrupted run from <out>.chunks/ (its finished units are kept); the results are "
                "byte-identical to an uninterrupted run's");
  cmd->add_option("--shard", args.shard,
                  "I/N: compute only shard I of N of the (row, realization) units into a shard folder; "
                  "`anchorbench merge` joins the N folders into the unsharded run's bytes");
}

constexpr long long kMaxSeed = std::numeric_limits<long long>::max();

// Every subcommand's arguments, and the CLI11 subcommand that fills them.
struct CommandLine {
  app::SimulateArgs simulate;
  app::ReplayArgs replay;
  app::RunArgs run;
  app::SweepArgs sweep;
  app::PdopStudyArgs study;
  app::RecordStudyArgs navigate;
  app::RecordStudyArgs explore;
  app::ConvertHanyangArgs convert;
  app::CalibrateArgs calibrate;
  app::MergeArgs merge;
  CLI::App* simulate_cmd = nullptr;
  CLI::App* replay_cmd = nullptr;
  CLI::App* run_cmd = nullptr;
  CLI::App* sweep_cmd = nullptr;
  CLI::App* study_cmd = nullptr;
  CLI::App* navigate_cmd = nullptr;
  CLI::App* explore_cmd = nullptr;
  CLI::App* convert_cmd = nullptr;
  CLI::App* calibrate_cmd = nullptr;
  CLI::App* merge_cmd = nullptr;
  CLI::App* list_cmd = nullptr;
};

void AddRecordingCommands(CLI::App& cli, CommandLine& c) {
  c.simulate_cmd = cli.add_subcommand("simulate", "Simulate one realization and write poses.csv, ranges.csv, anchors.csv");
  c.simulate_cmd->add_option("config", c.simulate.config, "Experiment config (YAML)")->required();
  c.simulate_cmd->add_option("--out", c.simulate.out, "Output folder (created if needed)")->required();
  c.simulate_cmd->add_option("--seed", c.simulate.seed, "Override the config's seed")->check(WholeNumber(0, kMaxSeed));
  c.simulate_cmd->add_option("--realization", c.simulate.realization, "Realization index (default 0)")
      ->check(WholeNumber(0, kMaxSeed));
  c.simulate_cmd->add_flag("--overwrite", c.simulate.overwrite, "Replace an output folder that holds files");
  c.simulate_cmd->add_option("--set", c.simulate.overrides, "Override a config value: KEY=VALUE (repeatable)");

  c.replay_cmd = cli.add_subcommand("replay", "Run the online initializers (estimator.triggers; by default the fixed "
                                              "window and the PDOP-gated one) on recorded data");
  c.replay_cmd->add_option("--poses", c.replay.poses, "poses.csv: t,tag_id,x,y,z (column aliases: docs/real_data.md)")
      ->required();
  c.replay_cmd->add_option("--ranges", c.replay.ranges,
                           "ranges.csv: t,tag_id,anchor_id,range; several files (e.g. one per anchor) are merged by time")
      ->required();
  c.replay_cmd->add_option("--anchors", c.replay.anchors, "anchors.csv: anchor_id,x,y,z[,bias] (truth, for errors)");
  c.replay_cmd->add_option("--config", c.replay.config, "Config whose 'estimator' section is used (default: defaults)");
  c.replay_cmd->add_option("--trace", c.replay.trace,
                           "Write one row per range: t,tag_id,anchor_id,range,accepted,n_accepted,pdop");
  c.replay_cmd->add_option("--certificate-trace", c.replay.certificate_trace,
                           "Write one row per evaluation of a trigger that solves (certified: each test, the region's "
                           "terms, the evidence, the stability): why an anchor waits (docs/real_data.md)");
  c.replay_cmd->add_option("--out", c.replay.out, "Folder for estimates.csv");
  c.replay_cmd->add_flag("--overwrite", c.replay.overwrite, "Replace an existing --out folder or trace file");
  c.replay_cmd->add_flag("--navigate", c.replay.navigate,
                         "Also run the navigation filter on the log's lowest tag with each trigger's anchors and "
                         "synthetic odometry (the config's 'navigation' section; docs/navigation.md) into --out");
  c.replay_cmd->add_option("--max-range-m", c.replay.policy.max_range_m,
                           "Drop ranges above this as implausible (default 1000)")
      ->check(FiniteNumber(1e-3, 1e7));
  c.replay_cmd->add_option("--average-poses-within-m", c.replay.policy.average_within_m,
                           "Two poses of a tag at one time within this are averaged and counted (default 0.05 m; "
                           "within 1 mm: one pose repeated)")
      ->check(FiniteNumber(0.0, 10.0));
  c.replay_cmd->add_option("--repeated-poses", c.replay.repeated_poses,
                           "Two poses of a tag at one time farther apart than --average-poses-within-m: error "
                           "(default), first, average")
      ->check(CLI::IsMember({"error", "first", "average"}));
  c.replay_cmd->add_option("--out-of-order", c.replay.out_of_order,
                           "A row older than one before it: sort (default: within --sort-window-s, counted), drop, error")
      ->check(CLI::IsMember({"error", "drop", "sort"}));
  c.replay_cmd->add_option("--sort-window-s", c.replay.policy.sort_window_s,
                           "With --out-of-order sort: how late a row may come (default 0.1 s; later is an error)")
      ->check(FiniteNumber(0.0, 3600.0));
  c.replay_cmd->add_option("--max-speed-mps", c.replay.policy.max_speed_mps,
                           "Drop a pose farther from its tag's last one than this speed allows, unless the next "
                           "agrees with it (default 50 m/s)")
      ->check(FiniteNumber(1e-3, 1e6));
  c.replay_cmd->add_flag("--strict", c.replay.policy.strict, "Every row that would be dropped is an error instead");
  c.replay_cmd->add_flag("--quiet", c.replay.quiet, "No progress line and no drop summary on stderr");

  c.convert_cmd = cli.add_subcommand(
      "convert-hanyang", "Convert a Hanyang outdoor UWB dataset case into poses.csv, ranges.csv, anchors.csv");
  c.convert_cmd->add_option("case", c.convert.case_folder, "Case folder (A3.csv ... A12.csv, trajectory.csv)")->required();
  c.convert_cmd->add_option("--out", c.convert.out, "Output folder (created if needed)")->required();
  c.convert_cmd->add_flag("--overwrite", c.convert.overwrite, "Replace an output folder that holds files");
}

void AddMonteCarloCommands(CLI::App& cli, CommandLine& c) {
  c.run_cmd = cli.add_subcommand("run", "Monte Carlo: every row x realization x anchor x trigger (estimator.triggers)");
  c.run_cmd->add_option("config", c.run.config, "Experiment config (YAML) with rows")->required();
  AddMonteCarloOptions(c.run_cmd, c.run);
  AddChunkOptions(c.run_cmd, c.run);
  c.run_cmd->add_option("--seed", c.run.seed, "Override the config's seed")->check(WholeNumber(0, kMaxSeed));
  c.run_cmd->add_option("--set", c.run.overrides, "Override a config value: KEY=VALUE, KEY a dotted path (repeatable)");

  c.merge_cmd = cli.add_subcommand("merge", "Join the shard folders of one run or sweep into its single results");
  c.merge_cmd->add_option("out", c.merge.out, "Output folder")->required();
  c.merge_cmd->add_option("shards", c.merge.shards, "Every shard folder of the run or sweep (--shard I/N), any order")
      ->required();
  c.merge_cmd->add_flag("--overwrite", c.merge.overwrite, "Replace an output folder that holds earlier results");
  c.merge_cmd->add_flag("--quiet", c.merge.quiet, "Do not print the table");

  c.sweep_cmd = cli.add_subcommand("sweep", "Run a config over a grid of values and tabulate each point");
  c.sweep_cmd->add_option("config", c.sweep.config, "Experiment config (YAML); its 'sweep' section gives axes")->required();
  c.sweep_cmd->add_option("--set", c.sweep.axes,
                          "An axis: KEY=VALUES, a list a,b,c or a range start:stop:step (repeatable)");
  AddMonteCarloOptions(c.sweep_cmd, c.sweep);
  AddChunkOptions(c.sweep_cmd, c.sweep);

  c.study_cmd = cli.add_subcommand("pdop-study",
                                   "Closest-point, LS, NLS and true PDOP side by side along random runs (Figs. 6-8)");
  c.study_cmd->add_option("config", c.study.config, "Experiment config (YAML); its base scenario is used")->required();
  AddMonteCarloOptions(c.study_cmd, c.study);
  c.study_cmd->add_option("--set", c.study.overrides, "Override a config value: KEY=VALUE, KEY a dotted path (repeatable)");
  c.study_cmd->add_option("--every", c.study.every,
                          "Checkpoint every N accepted samples: pdop_study.every (default 10)")
      ->check(WholeNumber(1, 1000000));
  c.study_cmd->add_option("--bin-s", c.study.bin_s, "Summary time bins in seconds, 0.01 to 120: pdop_study.bin_s (default 10)")
      ->check(FiniteNumber(0.01, 120.0));
  AddUnitOptions(c.study_cmd, c.study);

  c.navigate_cmd = cli.add_subcommand(
      "navigate", "Each trigger's anchors in a drifting robot's navigation filter, against the true anchors and none "
                  "(docs/navigation.md)");
  c.navigate_cmd->add_option("config", c.navigate.config, "Experiment config (YAML) with a 'navigation' section")
      ->required();
  AddMonteCarloOptions(c.navigate_cmd, c.navigate);
  c.navigate_cmd->add_option("--set", c.navigate.overrides, "Override a config value: KEY=VALUE, KEY a dotted path (repeatable)");
  AddUnitOptions(c.navigate_cmd, c.navigate);

  c.explore_cmd = cli.add_subcommand(
      "explore", "Closed loop: the robot's pattern alone against the pattern with guidance's detours, until every "
                 "anchor is certified (docs/guidance.md)");
  c.explore_cmd->add_option("config", c.explore.config, "Experiment config (YAML) with an 'exploration' section")
      ->required();
  AddMonteCarloOptions(c.explore_cmd, c.explore);
  c.explore_cmd->add_option("--set", c.explore.overrides, "Override a config value: KEY=VALUE, KEY a dotted path (repeatable)");
  AddUnitOptions(c.explore_cmd, c.explore);

  c.calibrate_cmd = cli.add_subcommand(
      "calibrate", "Fit scenario parameters so an experiment's table matches the published one (docs/calibration.md)");
  c.calibrate_cmd->add_option("config", c.calibrate.config, "Calibration file (YAML): experiment, parameters, fit")
      ->required();
  AddMonteCarloOptions(c.calibrate_cmd, c.calibrate, false);
  c.calibrate_cmd->add_option("--reuse", c.calibrate.reuse,
                              "A finished calibration's evaluations.csv: its evaluations of the same experiment, seed "
                              "and size are taken instead of recomputed");
}

int Dispatch(const CommandLine& c, const app::AppContext& context) {
  if (c.simulate_cmd->parsed()) return app::SimulateCommand(c.simulate, context);
  if (c.replay_cmd->parsed()) return app::ReplayCommand(c.replay, context);
  if (c.run_cmd->parsed()) return app::RunCommand(c.run, context);
  if (c.sweep_cmd->parsed()) return app::SweepCommand(c.sweep, context);
  if (c.study_cmd->parsed()) return app::RecordStudyCommand("pdop-study", c.study.WithSettings(), context);
  if (c.navigate_cmd->parsed()) return app::RecordStudyCommand("navigate", c.navigate, context);
  if (c.explore_cmd->parsed()) return app::RecordStudyCommand("explore", c.explore, context);
  if (c.calibrate_cmd->parsed()) return app::CalibrateCommand(c.calibrate, context);
  if (c.merge_cmd->parsed()) return app::MergeCommand(c.merge, context);
  if (c.convert_cmd->parsed()) return app::ConvertHanyangCommand(c.convert);
  if (c.list_cmd->parsed()) return app::ListCommand(context);
  return 1;
}

}  // namespace

// Usage errors exit like every other bad input: one line, code 2. Help is not an error.
int UsageError(const CLI::App& cli, const CLI::ParseError& e) {
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return cli.exit(e);  // --help
  std::cerr << "anchorbench: error: " << e.what() << " (see anchorbench --help)\n";
  return 2;
}

// The command line parsed and run; every error reported here, as its exit code.
int RunCommandLine(int argc, char** argv, const anchorbench::registry::Components& components,
                   anchorbench::engine::Executor& executor) {
  CLI::App cli{"anchorbench: online initialization of unknown UWB anchors (Delama et al., IROS 2025)"};
  cli.footer(kExitCodes);
  cli.require_subcommand(1);
  CommandLine command_line;
  AddRecordingCommands(cli, command_line);
  AddMonteCarloCommands(cli, command_line);
  command_line.list_cmd = cli.add_subcommand("list", "List the registered solvers, filters and triggers");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return UsageError(cli, e);
  }
  try {
    return Dispatch(command_line, {components, app::BuildRevision(), executor, &app::InterruptFlag()});
  } catch (const anchorbench::engine::Interrupted&) {
    std::cerr << "anchorbench: interrupted: no result folder written (finished chunks, where the command keeps "
                 "them, wait in <out>.chunks for --resume)\n";
    return 130;
  } catch (const anchorbench::schema::InputError& e) {
    std::cerr << "anchorbench: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "anchorbench: internal error: " << e.what() << '\n';
    return 3;
  }
}

int main(int argc, char** argv) {
  // A solve's O(N) arrays (residuals, trimmed sums, ranges less their offsets) are allocated and
  // freed at every evaluation; glibc's defaults give the larger ones fresh pages from the kernel
  // each time (mmap, or a heap top trimmed and grown again). Keeping freed memory in the process
  // makes a long replay's page faults those of its buffers alone (docs/method.md, "Cost").
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  app::InstallInterruptHandlers();
  const anchorbench::registry::Components components = [] {
    anchorbench::registry::Components parts = anchorbench::eval::MakeComponentsWithOracles();
    anchorbench::example_parts::RegisterExampleParts(parts);
    return parts;
  }();
#ifdef ANCHORBENCH_MPI
  app::MpiJob job(argc, argv, components);  // anchorbench-mpi: rank 0 runs the command, the others compute chunks
  if (job.worker()) return job.Serve();
  return job.Finish(RunCommandLine(argc, argv, components, job.executor()));
#else
  anchorbench::engine::LocalExecutor executor(components, &app::InterruptFlag());
  return RunCommandLine(argc, argv, components, executor);
#endif
}
