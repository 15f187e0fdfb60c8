#include "anchorbench/studies/calibration_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "anchorbench/studies/objective.hpp"
#include "anchorbench/io/format.hpp"

namespace anchorbench::studies {

using io::FormatFixed;
using io::FormatNumber;
using io::FormatOptional;
using report::PaperCell;

namespace {

std::string ShortMethod(const std::string& method) {
  return method == schema::kFixedWindowTrigger ? "fixed" : method == schema::kPaperTrigger ? "gated" : method;
}

bool Fitted(const schema::CalibrationSpec& spec, const PaperCell& cell) {
  return report::ValueOf(spec.fit_weight, cell.column) > 0.0;
}

struct Counts {
  int within = 0, scored = 0;                  // scored cells within +-25%
  int inside = 0, with_interval = 0;           // paper inside our interval
  int fitted_within = 0, fitted = 0;           // scored cells of fitted columns
  int held_out_within = 0, held_out = 0;       // scored cells of held-out columns
};

Counts Count(const schema::CalibrationSpec& spec, const std::vector<PaperCell>& cells) {
  Counts c;
  const report::PaperScore score = report::ScoreCells(cells);
  c.within = score.within, c.scored = score.cells, c.inside = score.inside_interval, c.with_interval = score.with_interval;
  for (const PaperCell& cell : cells) {
    if (!cell.scored) continue;
    const bool within = report::WithinQuarter(cell);
    if (Fitted(spec, cell)) {
      ++c.fitted, c.fitted_within += within;
    } else {
      ++c.held_out, c.held_out_within += within;
    }
  }
  return c;
}

// "mean (min-max)" of a count over the verification seeds.
std::string Spread(const std::vector<int>& values) {
  double sum = 0.0;
  for (int v : values) sum += v;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  return FormatFixed(sum / static_cast<double>(values.size()), 1) + " (" + std::to_string(*lo) + "-" +
         std::to_string(*hi) + ")";
}

std::string Columns(const schema::CalibrationSpec& spec, bool fitted) {
  std::string text;
  for (report::PaperColumn column : report::kPaperColumns) {
    const double w = report::ValueOf(spec.fit_weight, column);
    if ((w > 0.0) != fitted) continue;
    text += (text.empty() ? "" : ", ") + std::string(report::ToString(column)) +
            (fitted ? " (weight " + FormatNumber(w) + ")" : "");
  }
  return text.empty() ? "none" : text;
}

void WriteParameters(std::ostream& out, const CalibrationOutcome& o) {
  const std::vector<Evaluation>& all = o.log.evaluations();
  out << "## Parameters\n\n| key | bounds | provenance | as configured | calibrated |\n|---|---|---|---|---|\n";
  for (std::size_t p = 0; p < o.spec.parameters.size(); ++p) {
    const schema::FreeParameter& parameter = o.spec.parameters[p];
    out << "| `" << parameter.key << "` | [" << FormatNumber(parameter.min) << ", " << FormatNumber(parameter.max)
        << "] | " << parameter.provenance << " | " << all[o.result.hand].values[p] << " | "
        << all[o.result.best].values[p] << " |\n";
  }
}

// "mean (min-max)" of the objective over the verification seeds, of the before or after cells.
struct ObjectiveRange {
  double mean = 0.0, lo = HUGE_VAL, hi = -HUGE_VAL;
};
// The objective over the verification seeds, of the configured (before) or calibrated cells.
ObjectiveRange ObjectiveOverSeeds(const CalibrationOutcome& o, bool after, bool held_out) {
  ObjectiveRange spread;
  for (const Verification& v : o.verification) {
    const double value = Objective(after ? v.after : v.before, o.spec.fit_weight, held_out, o.spec.band);
    spread.mean += value;
    spread.lo = std::min(spread.lo, value), spread.hi = std::max(spread.hi, value);
  }
  spread.mean /= static_cast<double>(o.verification.size());
  return spread;
}

std::string ObjectiveSpread(const CalibrationOutcome& o, bool after, bool held_out) {
  const ObjectiveRange s = ObjectiveOverSeeds(o, after, held_out);
  return FormatFixed(s.mean, 4) + " (" + FormatFixed(s.lo, 4) + "-" + FormatFixed(s.hi, 4) + ")";
}

void WriteObjective(std::ostream& out, const CalibrationOutcome& o) {
  const std::vector<Evaluation>& all = o.log.evaluations();
  const Evaluation& hand = all[o.result.hand];
  const Evaluation& best = all[o.result.best];
  out << "\n## Objective\n\n"
      << "The weighted mean over the fitted cells of the squared log-ratio of ours to the paper"
      << (o.spec.band > 0.0 ? " outside +-" + FormatNumber(100.0 * o.spec.band) + "% of it (0 inside)" : "")
      << ". The held-out columns' value (weight 1 each) measures the prediction of what was not fitted. At the fit's "
         "seed and size, and at full size on the verification seeds (mean and range).\n\n"
      << "| | evaluation | fitted, fit seed | held out, fit seed | fitted, verification | held out, verification |\n"
         "|---|---|---|---|---|---|\n";
  for (const bool after : {false, true}) {
    const Evaluation& e = after ? best : hand;
    out << "| " << (after ? "calibrated" : "as configured") << " | " << (after ? o.result.best : o.result.hand)
        << (after ? " (" + e.stage + ")" : std::string()) << " | " << FormatFixed(e.objective, 4) << " | "
        << FormatFixed(Objective(o.fit.CellsOf(e), o.spec.fit_weight, true, o.spec.band), 4) << " | "
        << ObjectiveSpread(o, after, false) << " | " << ObjectiveSpread(o, after, true) << " |\n";
  }
}

void WriteVerification(std::ostream& out, const CalibrationOutcome& o) {
  out << "\n## Verification: " << o.full_realizations << " realizations per row on " << o.verification.size()
      << " seeds the fit never saw\n\n"
      << "Cells within +-25% count the scored cells (Avg, Med, Init, Ratio; not the fixed window's Init, which "
         "matches by construction). Fitted and held-out split them by column. 'Paper inside' counts the Avg, Med "
         "and Ratio cells whose paper value lies inside our 95% interval.\n\n"
      << "| seed | within +-25% before | after | fitted cells within, after | held-out cells within, after | "
         "paper inside, before | after |\n|---|---|---|---|---|---|---|\n";
  std::vector<int> before_within, after_within, fitted, held, before_inside, after_inside;
  Counts last;
  for (const Verification& v : o.verification) {
    const Counts b = Count(o.spec, v.before);
    const Counts a = Count(o.spec, v.after);
    last = a;
    out << "| " << v.seed << " | " << b.within << " / " << b.scored << " | " << a.within << " / " << a.scored << " | "
        << a.fitted_within << " / " << a.fitted << " | " << a.held_out_within << " / " << a.held_out << " | "
        << b.inside << " / " << b.with_interval << " | " << a.inside << " / " << a.with_interval << " |\n";
    before_within.push_back(b.within), after_within.push_back(a.within), fitted.push_back(a.fitted_within);
    held.push_back(a.held_out_within), before_inside.push_back(b.inside), after_inside.push_back(a.inside);
  }
  out << "| mean (range) | " << Spread(before_within) << " | " << Spread(after_within) << " | " << Spread(fitted)
      << " | " << Spread(held) << " | " << Spread(before_inside) << " | " << Spread(after_inside) << " |\n";
}

// Per cell over the verification seeds: the paper, our mean before and after, and on how many
// seeds each was within +-25%.
void WriteCells(std::ostream& out, const CalibrationOutcome& o) {
  out << "\n## Cell by cell at verification (mean over the seeds; within +-25% on how many)\n\n"
      << "| cell | fitted | paper | before | within | after | within |\n|---|---|---|---|---|---|---|\n";
  const std::size_t seeds = o.verification.size();
  for (std::size_t c = 0; c < o.verification.front().after.size(); ++c) {
    const PaperCell& head = o.verification.front().after[c];
    if (!head.scored) continue;
    double before = 0.0, after = 0.0;
    int before_n = 0, after_n = 0, before_within = 0, after_within = 0;
    for (const Verification& v : o.verification) {
      if (v.before[c].ours) before += *v.before[c].ours, ++before_n;
      if (v.after[c].ours) after += *v.after[c].ours, ++after_n;
      before_within += report::WithinQuarter(v.before[c]);
      after_within += report::WithinQuarter(v.after[c]);
    }
    const int decimals = report::Decimals(head.column);
    out << "| " << CellName(head, o.row_names) << " | " << (Fitted(o.spec, head) ? "yes" : "held out") << " | "
        << FormatFixed(head.paper, decimals) << " | " << (before_n ? FormatFixed(before / before_n, decimals) : "-")
        << " | " << before_within << " / " << seeds << " | " << (after_n ? FormatFixed(after / after_n, decimals) : "-")
        << " | " << after_within << " / " << seeds << " |\n";
  }
}

void WriteProfiles(std::ostream& out, const CalibrationOutcome& o) {
  const std::vector<Evaluation>& all = o.log.evaluations();
  const double best = all[o.result.best].objective;
  const ObjectiveRange calibrated = ObjectiveOverSeeds(o, true, false);
  const double noise = calibrated.hi - calibrated.lo;  // rises below it are noise
  out << "\n## Identifiability: the objective around the calibrated point\n\n"
      << "Each parameter moved alone by +-1 and +-2.5 steps of " << FormatNumber(o.spec.profile_step)
      << " x its range (at the fit's seed and size); the rise over the calibrated objective "
      << FormatFixed(best, 4) << ". The calibrated objective's spread over the verification seeds is "
      << FormatFixed(noise, 4) << ": a rise below it does not tell the values apart. A parameter is 'sharp' if "
         "it rises above that at one step on every side it can move, 'bounded' if at 2.5 steps, else the table does "
         "not determine it within its bounds.\n\n"
      << "| key | -2.5 | -1 | +1 | +2.5 | verdict |\n|---|---|---|---|---|---|\n";
  for (std::size_t p = 0; p < o.spec.parameters.size(); ++p) {
    std::map<double, double> rise;
    for (const ProfilePoint& point : o.result.profile) {
      if (point.parameter == p) rise[point.steps] = all[point.evaluation].objective - best;
    }
    auto side_rises = [&](double steps) {  // the smallest rise over the sides that exist
      double smallest = HUGE_VAL;
      bool any = false;
      for (double s : {-steps, steps}) {
        if (rise.count(s)) smallest = std::min(smallest, rise[s]), any = true;
      }
      return any ? smallest : -HUGE_VAL;
    };
    const std::string verdict = side_rises(1.0) > noise   ? "sharp"
                                : side_rises(2.5) > noise ? "bounded"
                                                          : "not determined";
    out << "| `" << o.spec.parameters[p].key << "` |";
    for (double steps : {-2.5, -1.0, 1.0, 2.5}) {
      if (rise.count(steps)) {
        out << " " << (rise[steps] >= 0 ? "+" : "") << FormatFixed(rise[steps], 4) << " |";
      } else {
        out << " bound |";
      }
    }
    out << " " << verdict << " |\n";
  }
}

// Which cells the search reached at all: a cell within +-25% somewhere but not at the optimum
// cannot be had together with the others there; one never within was not reachable in the box.
void WriteReachability(std::ostream& out, const CalibrationOutcome& o) {
  const std::vector<Evaluation>& all = o.log.evaluations();
  out << "\n## Reachability over all " << all.size() << " evaluations (fit size)\n\n"
      << "| cell | fitted | at the calibrated point | evaluations within +-25% | closest ratio ours / paper | verdict |\n"
      << "|---|---|---|---|---|---|\n";
  const std::vector<PaperCell> best_cells = o.fit.CellsOf(all[o.result.best]);
  for (std::size_t c = 0; c < best_cells.size(); ++c) {
    if (!best_cells[c].scored) continue;
    int within = 0;
    double closest = HUGE_VAL;
    std::optional<double> closest_ratio;
    for (const Evaluation& e : all) {
      const PaperCell cell = o.fit.CellsOf(e)[c];
      within += report::WithinQuarter(cell);
      const std::optional<double> log_ratio = LogRatio(cell);
      if (log_ratio && std::abs(*log_ratio) < closest) closest = std::abs(*log_ratio), closest_ratio = std::exp(*log_ratio);
    }
    const bool at_best = report::WithinQuarter(best_cells[c]);
    const std::string verdict = at_best ? "reached" : within > 0 ? "reachable alone, not with the others" : "not reached in the box";
    out << "| " << CellName(best_cells[c], o.row_names) << " | " << (Fitted(o.spec, best_cells[c]) ? "yes" : "held out")
        << " | " << (at_best ? "within" : "outside") << " | " << within << " / " << all.size() << " | "
        << (closest_ratio ? FormatFixed(*closest_ratio, 2) : "-") << " | " << verdict << " |\n";
  }
}

}  // namespace

std::string CellName(const PaperCell& cell, const std::vector<std::string>& row_names) {
  return row_names[static_cast<std::size_t>(cell.row)] + "." + ShortMethod(cell.method) + "." + report::ToString(cell.column);
}

void WriteCalibrationMarkdown(std::ostream& out, const CalibrationOutcome& o) {
  out << "# Calibration of " << o.spec.experiment_path << " (" << o.spec.path << ")\n\n"
      << "Fitted columns: " << Columns(o.spec, true) << ". Held out: " << Columns(o.spec, false) << ". "
      << o.log.evaluations().size() << " evaluations of " << o.spec.realizations << " realizations per row at seed "
      << o.spec.seed << " (" << o.spec.global.algorithm << " up to " << o.spec.global.max_evaluations << ", then "
      << o.spec.local.algorithm << " up to " << o.spec.local.max_evaluations << ", then the profiles).\n\n";
  WriteParameters(out, o);
  WriteObjective(out, o);
  WriteVerification(out, o);
  WriteCells(out, o);
  WriteProfiles(out, o);
  WriteReachability(out, o);
}

void WriteEvaluationsCsv(std::ostream& out, const EvaluationLog& log) {
  out << log.Header() << '\n';
  for (std::size_t i = 0; i < log.evaluations().size(); ++i) out << log.Line(i) << '\n';
}

void WriteVerificationCsv(std::ostream& out, const CalibrationOutcome& o) {
  out << "seed,config,row,method,column,paper,ours,lo,hi,scored,fitted,within_25pct,paper_inside\n";
  for (const Verification& v : o.verification) {
    for (const auto& [name, cells] : {std::pair{"before", &v.before}, std::pair{"after", &v.after}}) {
      for (const PaperCell& cell : *cells) {
        out << v.seed << ',' << name << ',' << o.row_names[static_cast<std::size_t>(cell.row)] << ',' << cell.method << ','
            << report::ToString(cell.column) << ',' << FormatNumber(cell.paper) << ',' << FormatOptional(cell.ours) << ','
            << FormatOptional(cell.lo) << ',' << FormatOptional(cell.hi) << ',' << (cell.scored ? 1 : 0) << ','
            << (Fitted(o.spec, cell) ? 1 : 0) << ',' << (report::WithinQuarter(cell) ? 1 : 0) << ','
            << (report::PaperInsideInterval(cell) ? 1 : 0) << '\n';
      }
    }
  }
}

void WriteProfileCsv(std::ostream& out, const CalibrationOutcome& o) {
  const std::vector<Evaluation>& all = o.log.evaluations();
  out << "key,steps,value,objective,rise\n";
  for (const ProfilePoint& point : o.result.profile) {
    const Evaluation& e = all[point.evaluation];
    out << o.spec.parameters[point.parameter].key << ',' << FormatNumber(point.steps) << ','
        << e.values[point.parameter] << ',' << FormatNumber(e.objective) << ','
        << FormatNumber(e.objective - all[o.result.best].objective) << '\n';
  }
}

std::string CalibratedConfigYaml(const CalibrationOutcome& o, const std::string& experiment_file_name) {
  const Evaluation& best = o.log.evaluations()[o.result.best];
  std::string text = "# " + experiment_file_name + " with its scenario calibrated to the table its rows carry, by\n" +
                     "# `anchorbench calibrate " + o.spec.path + "` (its results: calibration.md). Do not edit:\n" +
                     "# the main command rewrites it. Each value's bounds and provenance are in the comment.\n\n" +
                     "base: " + experiment_file_name + "\n";
  // Keys in the spec's order, nested: each path's sections opened where they differ from the last.
  std::vector<std::string> open;
  for (std::size_t p = 0; p < o.spec.parameters.size(); ++p) {
    const schema::FreeParameter& parameter = o.spec.parameters[p];
    std::vector<std::string> parts;
    for (std::size_t start = 0;;) {
      const std::size_t dot = parameter.key.find('.', start);
      parts.push_back(parameter.key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
    std::size_t shared = 0;
    while (shared < open.size() && shared + 1 < parts.size() && open[shared] == parts[shared]) ++shared;
    open.resize(shared);
    for (std::size_t d = shared; d + 1 < parts.size(); ++d) {
      text += std::string(2 * d, ' ') + parts[d] + ":\n";
      open.push_back(parts[d]);
    }
    text += std::string(2 * (parts.size() - 1), ' ') + parts.back() + ": " + best.values[p] + "  # [" +
            FormatNumber(parameter.min) + ", " + FormatNumber(parameter.max) + "] " + parameter.provenance + "\n";
  }
  return text;
}

}  // namespace anchorbench::studies
