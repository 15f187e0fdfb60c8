#include "anchorbench/studies/fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlopt.hpp>

#include "anchorbench/studies/objective.hpp"
#include "anchorbench/estimator/nlopt_solver.hpp"
#include "anchorbench/io/format.hpp"

namespace anchorbench::studies {
namespace {

constexpr double kGrid = 1e4;                               // u is evaluated on a grid of 1/kGrid
constexpr double kProfileSteps[] = {-2.5, -1.0, 1.0, 2.5};  // x profile_step of the range

double Quantize(double u) { return std::round(std::clamp(u, 0.0, 1.0) * kGrid) / kGrid; }

}  // namespace

Fit::Fit(const schema::CalibrationSpec& spec, std::vector<report::PaperCell> targets, std::vector<double> hand_values,
         CellEvaluator evaluate, EvaluationLog* log, std::function<void(int, int)> progress)
    : spec_(spec),
      targets_(std::move(targets)),
      hand_values_(std::move(hand_values)),
      evaluate_(std::move(evaluate)),
      log_(log),
      progress_(std::move(progress)) {}

std::string Fit::ValueText(const schema::FreeParameter& parameter, double u) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", parameter.min + Quantize(u) * (parameter.max - parameter.min));
  return text;
}

std::vector<report::PaperCell> Fit::CellsOf(const Evaluation& evaluation) const {
  std::vector<report::PaperCell> cells = targets_;
  for (std::size_t c = 0; c < cells.size(); ++c) cells[c].ours = evaluation.ours[c];
  return cells;
}

int Fit::Total() const {
  return 1 + spec_.global.max_evaluations + spec_.local.max_evaluations +
         static_cast<int>(std::size(kProfileSteps) * spec_.parameters.size());
}

double Fit::EvaluateTexts(const std::vector<std::string>& texts, const std::vector<double>& u, const std::string& stage) {
  Evaluation evaluation{stage, texts, {}, 0.0};
  const std::vector<std::optional<double>>* known = log_->Find(texts);
  if (known) {
    evaluation.ours = *known;
  } else {
    std::vector<std::string> overrides;
    for (std::size_t p = 0; p < texts.size(); ++p) overrides.push_back(spec_.parameters[p].key + "=" + texts[p]);
    evaluation.ours = evaluate_(overrides);
  }
  evaluation.objective = Objective(CellsOf(evaluation), spec_.fit_weight, false, spec_.band);
  log_->Record(evaluation, !known);
  u_.push_back(u);
  if (progress_) progress_(static_cast<int>(u_.size()), Total());
  return evaluation.objective;
}

double Fit::Evaluate(const std::vector<double>& u, const std::string& stage) {
  std::vector<std::string> texts;
  std::vector<double> on_grid;
  for (std::size_t p = 0; p < u.size(); ++p) {
    texts.push_back(ValueText(spec_.parameters[p], u[p]));
    on_grid.push_back(Quantize(u[p]));
  }
  return EvaluateTexts(texts, on_grid, stage);
}

std::size_t Fit::Best() const {
  const std::vector<Evaluation>& all = log_->evaluations();
  std::size_t best = 0;
  for (std::size_t i = 1; i < all.size(); ++i) {
    if (all[i].objective < all[best].objective) best = i;
  }
  return best;
}

void Fit::RunStage(const schema::OptimizerStage& stage, const std::string& name, std::vector<double>* u) {
  if (stage.max_evaluations == 0) return;
  const unsigned dimension = static_cast<unsigned>(u->size());
  nlopt::opt optimizer(static_cast<nlopt::algorithm>(estimator::NloptSolver::AlgorithmNumber(stage.algorithm)),
                       dimension);
  optimizer.set_lower_bounds(std::vector<double>(dimension, 0.0));
  optimizer.set_upper_bounds(std::vector<double>(dimension, 1.0));
  optimizer.set_maxeval(stage.max_evaluations);
  optimizer.set_xtol_abs(1.0 / kGrid);  // finer than the grid the values are evaluated on is moot
  optimizer.set_initial_step(std::vector<double>(dimension, 0.1));
  struct Call {
    Fit* fit;
    const std::string* name;
    nlopt::opt* optimizer;
  } call{this, &name, &optimizer};
  optimizer.set_min_objective(
      [](const std::vector<double>& x, std::vector<double>&, void* data) {
        Call& c = *static_cast<Call*>(data);
        try {
          return c.fit->Evaluate(x, *c.name);
        } catch (...) {  // NLopt would swallow the message: keep it, stop, rethrow below
          c.fit->error_ = std::current_exception();
          c.optimizer->force_stop();
          return HUGE_VAL;
        }
      },
      &call);
  double value = 0.0;
  try {
    optimizer.optimize(*u, value);
  } catch (const std::exception&) {  // forced stop, round-off: the log holds every point anyway
  }
  if (error_) std::rethrow_exception(error_);
}

FitResult Fit::Run() {
  FitResult result;
  std::vector<std::string> hand_texts;
  std::vector<double> hand_u;
  for (std::size_t p = 0; p < hand_values_.size(); ++p) {
    const schema::FreeParameter& parameter = spec_.parameters[p];
    hand_texts.push_back(io::FormatNumber(hand_values_[p]));  // exactly the configured value
    hand_u.push_back((hand_values_[p] - parameter.min) / (parameter.max - parameter.min));
  }
  result.hand = log_->evaluations().size();
  EvaluateTexts(hand_texts, hand_u, "hand");

  std::vector<double> u(spec_.parameters.size(), 0.5);
  RunStage(spec_.global, "global", &u);
  u = u_[Best()];  // the local stage starts at the better of the configured and the global best
  RunStage(spec_.local, "local", &u);

  result.best = Best();
  const std::vector<double> best_u = u_[result.best];
  for (std::size_t p = 0; p < best_u.size(); ++p) {
    for (double steps : kProfileSteps) {
      std::vector<double> moved = best_u;
      moved[p] = Quantize(best_u[p] + steps * spec_.profile_step);
      if (moved[p] == best_u[p]) continue;  // at a bound
      Evaluate(moved, "profile");
      result.profile.push_back({p, steps, log_->evaluations().size() - 1});
    }
  }
  return result;
}

}  // namespace anchorbench::studies
