#include "anchorbench/engine/attempt.hpp"

#include "anchorbench/eval/attempt_evaluation.hpp"
#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::engine {

std::uint64_t SolverSeed(std::uint64_t seed, std::uint64_t realization, int anchor_id) {
  return sim::RandomStream(seed, realization, schema::kSolverStream, static_cast<std::uint32_t>(anchor_id)).NextU64();
}

const schema::AnchorTruth* TruthOf(const std::map<int, schema::AnchorTruth>* truth, int anchor_id) {
  if (!truth) return nullptr;
  const auto found = truth->find(anchor_id);
  return found == truth->end() ? nullptr : &found->second;
}

schema::Attempt AttemptOf(const estimator::AnchorInitializer& initializer, const std::optional<estimator::InitEvent>& event,
                  const std::string& method, const schema::AnchorTruth* truth) {
  schema::Attempt a;
  a.anchor_id = initializer.anchor_id();
  a.method = method;
  a.initialized = initializer.initialized();
  a.n_used = static_cast<int>(initializer.range_m().size());
  a.pdop_closest_point = initializer.pdop().Value();
  if (event) {
    a.t_init_s = event->t_s;
    a.n_used = event->n_used;
    a.pdop_closest_point = event->pdop_closest_point;
    a.solve = event->solve;
  } else if (const std::optional<estimator::InitEvent>& failed = initializer.last_failed_solve()) {
    a.solve = failed->solve;  // triggered, but every solve failed
    a.t_failed_solve_s = failed->t_s;
  }
  if (!a.initialized) a.why_not = initializer.why_not();
  if (a.solve) {
    a.status = std::string(estimator::ToString(a.solve->status));
  } else if (const std::optional<estimator::SolveStatus> refusal = initializer.trigger_refusal()) {
    a.status = std::string(estimator::ToString(*refusal));  // e.g. the certificate's: height_unobservable
  } else {
    a.status = a.n_used == 0 ? "no_data" : "not_triggered";
  }
  // The initializer's buffer is exactly the data of the solve (online triggers stop buffering at init).
  if (truth) a.evaluation = eval::Evaluate(initializer.p_world_tag(), a.initialized ? &*a.solve : nullptr, *truth);
  return a;
}

void AddOracleLatency(const eval::OracleLatency& oracle, schema::Attempt& attempt) {
  if (!attempt.evaluation) return;
  attempt.evaluation->t_first_s = oracle.t_first_s;
  attempt.evaluation->t_oracle_s = oracle.t_oracle_s;
  attempt.evaluation->latency_ratio = eval::LatencyRatio(oracle, attempt.initialized ? attempt.t_init_s : std::nullopt);
  attempt.evaluation->t_ideal_s = oracle.t_ideal_s;
  attempt.evaluation->ideal_latency_ratio = eval::LatencyRatio(oracle, oracle.t_ideal_s);
}

}  // namespace anchorbench::engine
