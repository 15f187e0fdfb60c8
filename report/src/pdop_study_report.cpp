#include "anchorbench/report/pdop_study_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "anchorbench/io/format.hpp"
#include "anchorbench/report/summary.hpp"

namespace anchorbench::report {
namespace {

using io::FormatFixed;
using io::FormatNumber;
using schema::kPdopMethods;
using schema::PdopCheckpoint;
using schema::PdopMethod;
using schema::PdopMethodName;

// Fig. 7 spans the first 110 s after an anchor's first range: the time bins stop at 120 s.
constexpr double kFigure7Span_s = 120.0;

double Median(const std::vector<double>& values) { return Percentile(values, 0.5).value_or(std::nan("")); }

void WriteTraceRows(std::ostream& out, const std::vector<PdopCheckpoint>& checkpoints) {
  out << "realization,anchor_id,n,t,pdop_closest_point,pdop_ls,pdop_nls,pdop_true,bias_aware_dop,ls_err_m,nls_err_m,"
         "dop4_closest_point,dop4_confidence\n";
  for (const PdopCheckpoint& c : checkpoints) {
    out << c.realization << ',' << c.anchor_id << ',' << c.n << ',' << FormatNumber(c.t_s);
    for (double value : c.pdop) out << ',' << FormatNumber(value);
    out << ',' << FormatNumber(c.bias_aware_dop) << ',' << io::FormatOptional(c.ls_error_m) << ',' << io::FormatOptional(c.nls_error_m)
        << ',' << FormatNumber(c.dop4_closest_point) << ',' << FormatNumber(c.dop4_confidence) << '\n';
  }
}

// Fig. 7 left: per 10 s bin and method, the median of (estimate - true) and the share of
// overconfident values (estimate < true), over checkpoints where both are finite.
void WriteBins(std::ostream& md, const std::vector<PdopCheckpoint>& checkpoints, double bin_s) {
  md << "\n## PDOP estimate minus true PDOP, per " << bin_s
     << " s since the anchor's first range\n\nmedian (estimate - true) / overconfident share (estimate < true)\n\n| bin (s) |";
  for (PdopMethod m : kPdopMethods)
    if (m != PdopMethod::kTrue) md << ' ' << PdopMethodName(m) << " |";
  md << " checkpoints |\n|---|---|---|---|---|\n";
  std::map<int, std::vector<const PdopCheckpoint*>> bins;
  for (const PdopCheckpoint& c : checkpoints) bins[static_cast<int>(c.t_s / bin_s)].push_back(&c);
  for (const auto& [bin, members] : bins) {
    if (bin * bin_s >= kFigure7Span_s) break;
    md << "| " << bin * bin_s << "-" << (bin + 1) * bin_s << " |";
    for (PdopMethod m : kPdopMethods) {
      if (m == PdopMethod::kTrue) continue;
      std::vector<double> differences;
      int overconfident = 0;
      for (const PdopCheckpoint* c : members) {
        const double estimate = c->pdop[static_cast<int>(m)], truth = c->pdop[static_cast<int>(PdopMethod::kTrue)];
        if (!std::isfinite(estimate) || !std::isfinite(truth)) continue;
        differences.push_back(estimate - truth);
        overconfident += estimate < truth;
      }
      md << ' ' << FormatFixed(Median(differences), 2) << " / "
         << (differences.empty() ? "-" : FormatFixed(100.0 * overconfident / differences.size(), 0) + "%") << " |";
    }
    md << ' ' << members.size() << " |\n";
  }
}

// A DOP used as the trigger: at the first checkpoint of each (realization, anchor) where it is
// below the threshold (and the NLS solved), the NLS solution there is the initialization.
struct TriggerOutcome {
  std::vector<const PdopCheckpoint*> fired;  // one per initialized anchor, where it fired at a checkpoint
  std::vector<double> times, samples, errors;
  int bad = 0;  // errors > 1 m
};

template <typename Dop>
TriggerOutcome FireAt(const std::vector<PdopCheckpoint>& checkpoints, Dop dop, double threshold) {
  std::map<std::pair<int, int>, const PdopCheckpoint*> first;  // (realization, anchor) -> trigger
  for (const PdopCheckpoint& c : checkpoints) {
    const auto key = std::make_pair(c.realization, c.anchor_id);
    if (!first.count(key) && dop(c) < threshold && c.nls_error_m) first[key] = &c;
  }
  TriggerOutcome outcome;
  for (const auto& [key, c] : first) {
    outcome.fired.push_back(c);
    outcome.times.push_back(c->t_s);
    outcome.samples.push_back(c->n);
    outcome.errors.push_back(*c->nls_error_m);
    outcome.bad += *c->nls_error_m > 1.0;
  }
  return outcome;
}

// "initialized | median t | median n | median error | mean error | > 1 m" cells of an outcome.
std::string OutcomeCells(const TriggerOutcome& o, int anchors) {
  const double count = static_cast<double>(o.errors.size());
  return std::to_string(o.errors.size()) + " / " + std::to_string(anchors) + " | " + FormatFixed(Median(o.times), 1) +
         " | " + FormatFixed(Median(o.samples), 0) + " | " + FormatFixed(Median(o.errors), 3) + " | " +
         FormatFixed(Mean(o.errors).value_or(std::nan("")), 3) + " | " + (count > 0 ? FormatFixed(100.0 * o.bad / count, 1) + "%" : "-");
}

// Figs. 7/8 right: each method as the trigger at the threshold.
void WriteTriggers(std::ostream& md, const std::vector<PdopCheckpoint>& checkpoints, double threshold, int anchors) {
  md << "\n## Each PDOP as the trigger (threshold " << threshold
     << "), initialized with LS + NLS at that checkpoint\n\n"
        "| trigger | initialized | median t (s) | median n | median error (m) | mean error (m) | > 1 m | bias-aware DOP > threshold |\n"
        "|---|---|---|---|---|---|---|---|\n";
  for (PdopMethod m : kPdopMethods) {
    const TriggerOutcome o =
        FireAt(checkpoints, [m](const PdopCheckpoint& c) { return c.pdop[static_cast<int>(m)]; }, threshold);
    int bias_aware_above = 0;
    for (const PdopCheckpoint* c : o.fired) bias_aware_above += c->bias_aware_dop > threshold;
    const double count = static_cast<double>(o.fired.size());
    md << "| " << PdopMethodName(m) << (m == PdopMethod::kTrue ? " (oracle)" : "") << " | " << OutcomeCells(o, anchors)
       << " | " << (count > 0 ? FormatFixed(100.0 * bias_aware_above / count, 0) + "%" : "-") << " |\n";
  }
}

// The bias-aware DOPs (ours): each online proxy against the true bias-aware DOP, and each as the
// trigger at its own threshold, measured as the PDOP triggers above, so the two tables compare.
struct BiasAwareDop {
  const char* name;
  double PdopCheckpoint::*value;
  double threshold;
};

void WriteBiasAware(std::ostream& md, const std::vector<PdopCheckpoint>& checkpoints, const std::vector<BiasAwareDop>& dops,
                    int anchors) {
  md << "\n## The bias-aware DOPs (ours): proxies against the true one, and each as the trigger\n\n"
        "| DOP | threshold | below the true bias-aware DOP | initialized | median t (s) | median n | median error (m) "
        "| mean error (m) | > 1 m |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const BiasAwareDop& dop : dops) {
    long finite = 0, below = 0;
    for (const PdopCheckpoint& c : checkpoints) {
      if (std::isfinite(c.*dop.value) && std::isfinite(c.bias_aware_dop)) {
        ++finite;
        below += c.*dop.value < c.bias_aware_dop;
      }
    }
    const TriggerOutcome o =
        FireAt(checkpoints, [&dop](const PdopCheckpoint& c) { return c.*dop.value; }, dop.threshold);
    const bool oracle = dop.value == &PdopCheckpoint::bias_aware_dop;
    md << "| " << dop.name << " | " << FormatNumber(dop.threshold) << " | "
       << (oracle ? "-" : finite ? FormatFixed(100.0 * below / finite, 1) + "%" : "-") << " | "
       << OutcomeCells(o, anchors) << " |\n";
  }
}

// The certified trigger (ours) on the same runs, measured as the DOP triggers above, with why the
// anchors it did not initialize were left.
void WriteCertified(std::ostream& md, const std::vector<schema::CertifiedOutcome>& outcomes, double accuracy_m,
                    int anchors) {
  TriggerOutcome o;
  std::map<std::string, int> left;  // status -> anchors not initialized
  for (const schema::CertifiedOutcome& c : outcomes) {
    if (!c.error_m) {
      ++left[c.status];
      continue;
    }
    o.times.push_back(*c.t_s);
    o.samples.push_back(c.n);
    o.errors.push_back(*c.error_m);
    o.bad += *c.error_m > 1.0;
  }
  md << "\n## The certified trigger (ours, D = " << FormatNumber(accuracy_m)
     << " m) on the same runs, with the configured estimator\n\n"
        "| trigger | initialized | median t (s) | median n | median error (m) | mean error (m) | > 1 m | not initialized |\n"
        "|---|---|---|---|---|---|---|---|\n| certified | "
     << OutcomeCells(o, anchors) << " | ";
  std::string reasons;
  for (const auto& [status, count] : left) reasons += (reasons.empty() ? "" : ", ") + std::to_string(count) + " " + status;
  md << (reasons.empty() ? "-" : reasons) << " |\n";
}

}  // namespace

void WritePdopTrace(std::ostream& out, const std::vector<PdopCheckpoint>& checkpoints) { WriteTraceRows(out, checkpoints); }

void WritePdopStudyMarkdown(std::ostream& md, const schema::ExperimentConfig& config, const schema::PdopStudy& study,
                            int every, double bin_s) {
  const schema::UnderestimateStats& s = study.stats;
  std::vector<double> ratios = s.ratios_below;
  std::sort(ratios.begin(), ratios.end());
  md << "# " << config.name << ": the PDOP triggers side by side\n\n" << config.realizations
     << " realizations, sigma_d = " << config.scenario.ranging.sigma_range_m << " m, a checkpoint every " << every
     << " accepted samples.\n\n## Is the closest-point PDOP conservative? (Theorem 3.1)\n\n"
     << "Over all " << s.samples << " accepted samples with both values finite, the closest-point PDOP was below the "
     << "true PDOP in " << s.below << " (" << FormatFixed(s.samples ? 100.0 * s.below / s.samples : 0.0, 2) << "%)";
  if (!ratios.empty()) {
    md << "; there, estimate / true had median " << FormatFixed(ratios[ratios.size() / 2], 3) << " and minimum "
       << FormatFixed(ratios.front(), 3);
  }
  auto percent = [](long part, long whole) { return whole ? FormatFixed(100.0 * part / whole, 2) + "%" : std::string("-"); };
  md << ".\n\nIn Theorem 3.1's exact setting (true distances, so p_C is the truly closest sample) it was below in "
     << s.ideal_below << " (" << percent(s.ideal_below, s.samples) << "); among the " << s.ideal_samples_precondition
     << " samples where the theorem's precondition held, in " << s.ideal_below_precondition << " ("
     << percent(s.ideal_below_precondition, s.ideal_samples_precondition) << ").\n";

  WriteBins(md, study.checkpoints, bin_s);
  WriteTriggers(md, study.checkpoints, config.estimator.trigger.pdop_threshold, study.anchors);
  const schema::TriggerConfig& trigger = config.estimator.trigger;
  WriteBiasAware(md, study.checkpoints,
                 {{"dop4_closest_point", &PdopCheckpoint::dop4_closest_point, trigger.bias_aware_threshold},
                  {"dop4_confidence", &PdopCheckpoint::dop4_confidence, trigger.confidence_threshold},
                  {"dop4_true (oracle)", &PdopCheckpoint::bias_aware_dop, trigger.bias_aware_threshold}},
                 study.anchors);
  WriteCertified(md, study.certified, config.estimator.certificate.accuracy_m, study.anchors);
}

}  // namespace anchorbench::report
