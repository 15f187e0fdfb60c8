// anchorbench: Monte Carlo simulation and benchmarking of online UWB anchor initialization.
// The only file that sees CLI11: it maps the command line onto the commands of commands.hpp.
#include <iostream>

#include <CLI/CLI.hpp>

#include "anchorbench/experiments/commands.hpp"
#include "anchorbench/experiments/input_error.hpp"

namespace ex = anchorbench::experiments;

namespace {

// The options every Monte Carlo command shares (run, sweep, pdop-study).
template <typename Args>
void AddMonteCarloOptions(CLI::App* cmd, Args& args) {
  cmd->add_option("--out", args.out, "Output folder (default results/<config name>/)");
  cmd->add_option("--threads", args.threads, "OpenMP threads (default: all cores)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--realizations", args.realizations, "Override the realizations per row")->check(CLI::PositiveNumber);
  cmd->add_flag("--quiet", args.quiet, "No progress output");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"anchorbench: online initialization of unknown UWB anchors (Delama et al., IROS 2025)"};
  app.require_subcommand(1);

  ex::SimulateArgs simulate;
  CLI::App* simulate_cmd =
      app.add_subcommand("simulate", "Simulate one realization and write poses.csv, ranges.csv, anchors.csv");
  simulate_cmd->add_option("config", simulate.config, "Experiment config (YAML)")->required();
  simulate_cmd->add_option("--out", simulate.out, "Output folder (created if needed)")->required();
  simulate_cmd->add_option("--seed", simulate.seed, "Override the config's seed");
  simulate_cmd->add_option("--realization", simulate.realization, "Realization index (default 0)");
  simulate_cmd->add_option("--set", simulate.overrides, "Override a config value: KEY=VALUE (repeatable)");

  ex::ReplayArgs replay;
  CLI::App* replay_cmd =
      app.add_subcommand("replay", "Run the online initializers (estimator.triggers; by default the fixed window "
                                   "and the PDOP-gated one) on recorded data");
  replay_cmd->add_option("--poses", replay.poses, "poses.csv: t,tag_id,x,y,z")->required();
  replay_cmd->add_option("--ranges", replay.ranges, "ranges.csv: t,tag_id,anchor_id,range")->required();
  replay_cmd->add_option("--anchors", replay.anchors, "anchors.csv: anchor_id,x,y,z[,bias] (truth, for errors)");
  replay_cmd->add_option("--config", replay.config, "Config whose 'estimator' section is used (default: defaults)");
  replay_cmd->add_option("--trace", replay.trace,
                         "Write one row per range: t,tag_id,anchor_id,range,accepted,n_accepted,pdop");
  replay_cmd->add_option("--out", replay.out, "Folder for estimates.csv");

  ex::RunArgs run;
  CLI::App* run_cmd = app.add_subcommand("run", "Monte Carlo: every row x realization x anchor x trigger (estimator.triggers)");
  run_cmd->add_option("config", run.config, "Experiment config (YAML) with rows")->required();
  AddMonteCarloOptions(run_cmd, run);
  run_cmd->add_option("--seed", run.seed, "Override the config's seed");
  run_cmd->add_option("--set", run.overrides, "Override a config value: KEY=VALUE, KEY a dotted path (repeatable)");

  ex::SweepArgs sweep;
  CLI::App* sweep_cmd = app.add_subcommand("sweep", "Run a config over a grid of values and tabulate each point");
  sweep_cmd->add_option("config", sweep.config, "Experiment config (YAML); its 'sweep' section gives axes")->required();
  sweep_cmd->add_option("--set", sweep.axes, "An axis: KEY=VALUES, a list a,b,c or a range start:stop:step (repeatable)");
  AddMonteCarloOptions(sweep_cmd, sweep);

  ex::PdopStudyArgs study;
  CLI::App* study_cmd = app.add_subcommand(
      "pdop-study", "Closest-point, LS, NLS and true PDOP side by side along random runs (Figs. 6-8)");
  study_cmd->add_option("config", study.config, "Experiment config (YAML); its base scenario is used")->required();
  AddMonteCarloOptions(study_cmd, study);
  study_cmd->add_option("--every", study.every, "Checkpoint every N accepted samples (default 10)")->check(CLI::PositiveNumber);
  study_cmd->add_option("--bin-s", study.bin_s, "Summary time bins in seconds (default 10)")->check(CLI::PositiveNumber);

  ex::ConvertHanyangArgs convert;
  CLI::App* convert_cmd = app.add_subcommand(
      "convert-hanyang", "Convert a Hanyang outdoor UWB dataset case into poses.csv, ranges.csv, anchors.csv");
  convert_cmd->add_option("case", convert.case_folder, "Case folder (A3.csv ... A12.csv, trajectory.csv)")->required();
  convert_cmd->add_option("--out", convert.out, "Output folder (created if needed)")->required();

  CLI::App* list_cmd = app.add_subcommand("list", "List the registered solvers, filters and triggers");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (simulate_cmd->parsed()) return ex::SimulateCommand(simulate);
    if (replay_cmd->parsed()) return ex::ReplayCommand(replay);
    if (run_cmd->parsed()) return ex::RunCommand(run);
    if (sweep_cmd->parsed()) return ex::SweepCommand(sweep);
    if (study_cmd->parsed()) return ex::PdopStudyCommand(study);
    if (convert_cmd->parsed()) return ex::ConvertHanyangCommand(convert);
    if (list_cmd->parsed()) return ex::ListCommand();
  } catch (const ex::InputError& e) {
    std::cerr << "anchorbench: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "anchorbench: internal error: " << e.what() << '\n';
    return 3;
  }
  return 1;
}
