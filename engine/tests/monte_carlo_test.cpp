#include "anchorbench/engine/monte_carlo.hpp"

#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/testing/components.hpp"
#include "anchorbench/testing/small_table.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::engine {
namespace {

using anchorbench::testing::AllComponents;
using anchorbench::testing::SmallTable;

// Every deterministic field of every attempt, doubles to the last bit.
std::string Outputs(const schema::ExperimentConfig& config, int threads) {
  std::ostringstream out;
  out << std::hexfloat;
  for (const schema::Attempt& a : RunMonteCarlo(config, AllComponents(), {threads, nullptr})) {
    out << a.row << ' ' << a.realization << ' ' << a.anchor_id << ' ' << a.method << ' ' << a.initialized << ' '
        << a.t_init_s.value_or(-1.0) << ' ' << a.n_used << ' ' << a.pdop_closest_point << ' ' << a.status;
    if (a.solve) out << ' ' << a.solve->p_world_anchor.transpose() << ' ' << a.solve->bias_m << ' ' << a.solve->alpha;
    if (a.evaluation) {
      out << ' ' << a.evaluation->pdop_true << ' ' << a.evaluation->bias_aware_dop.value_or(-1.0) << ' '
          << a.evaluation->error_m.value_or(-1.0) << ' ' << a.crlb_m.value_or(-1.0);
    }
    out << '\n';
  }
  return out.str();
}

TEST(MonteCarlo, BitIdenticalForAnyThreadCount) {
  const schema::ExperimentConfig config = SmallTable();
  const std::string one = Outputs(config, 1);
  EXPECT_EQ(one, Outputs(config, 2));
  EXPECT_EQ(one, Outputs(config, 3));  // more threads than cores, uneven split
}

TEST(MonteCarlo, AllTriggersAndFiltersAreBitIdenticalForAnyThreadCount) {
  schema::ExperimentConfig config = SmallTable();
  config.realizations = 3;
  const std::vector<std::string> triggers = {"pdop_closest_point", "pdop_ls", "pdop_nls", "pdop_true",
                                             "fixed_window", "sample_count", "timeout"};
  for (schema::RowConfig& row : config.rows) {
    row.estimator.triggers = triggers;
    row.estimator.solver = "lm_l2";
    row.estimator.filter.kind = "ransac";  // the first row with our RANSAC as it comes
  }
  estimator::RansacOptions& table_ii = config.rows.back().estimator.filter.ransac;  // the last the paper's:
  table_ii.scheme = estimator::RansacScheme::kFullSolve;
  table_ii.subset_size = 20;  // 20 subsets: a quick RANSAC
  table_ii.outlier_fraction = 0.1;
  table_ii.success_probability = 0.9;
  const std::string one = Outputs(config, 1);
  EXPECT_EQ(one, Outputs(config, 2));
  const std::vector<schema::Attempt> attempts = RunMonteCarlo(config, AllComponents(), {2, nullptr});
  ASSERT_EQ(attempts.size(), 2u * 3u * 4u * triggers.size());
  for (std::size_t i = 0; i < attempts.size(); ++i) {
    EXPECT_EQ(attempts[i].method, triggers[i % triggers.size()]);  // anchor by anchor, in list order
    EXPECT_GE(attempts[i].compute_s, 0.0);
  }
}

TEST(MonteCarlo, EveryAnchorIsOneAttemptPerStrategyAndNothingIsNan) {
  const schema::ExperimentConfig config = SmallTable();
  const std::vector<schema::Attempt> attempts = RunMonteCarlo(config, AllComponents(), {2, nullptr});
  ASSERT_EQ(attempts.size(), 2u * 6u * 4u * 2u);  // rows x realizations x anchors x strategies
  for (const schema::Attempt& a : attempts) {
    EXPECT_FALSE(a.status.empty());
    if (a.initialized) {
      ASSERT_TRUE(a.evaluation->error_m.has_value());
      EXPECT_TRUE(std::isfinite(*a.evaluation->error_m));
    } else {
      EXPECT_FALSE(a.evaluation->error_m.has_value());
    }
  }
  const std::string text = Outputs(config, 2);
  EXPECT_EQ(text.find("nan"), std::string::npos);
}

TEST(MonteCarlo, ExactlyStraightRunsRecordDegenerateStatusesAndNeverAbort) {
  schema::ExperimentConfig config = SmallTable();
  for (schema::RowConfig& row : config.rows) {
    row.scenario.trajectory.fraction_straight = 1.0;
    row.scenario.trajectory.fraction_planar = 0.0;
    row.scenario.ranging.sigma_position_m = 0.0;  // exactly collinear tag positions
  }
  const std::vector<schema::Attempt> attempts = RunMonteCarlo(config, AllComponents(), {1, nullptr});
  int degenerate = 0;
  for (const schema::Attempt& a : attempts) {
    if (a.method == schema::kPaperTrigger) {
      EXPECT_FALSE(a.initialized);  // the PDOP of a straight line is infinite
    }
    degenerate += a.status == "degenerate_geometry";
  }
  EXPECT_GT(degenerate, 0);
  EXPECT_EQ(Outputs(config, 1).find("nan"), std::string::npos);
}

TEST(MonteCarlo, TheConfiguredSolverIsTheOneThatRuns) {
  schema::ExperimentConfig config = SmallTable();
  config.rows.resize(1);
  const std::vector<schema::Attempt> adaptive = RunMonteCarlo(config, AllComponents(), {1, nullptr});
  config.rows[0].estimator.solver = "ls_double";  // closed form: no kernel, alpha stays 2
  const std::vector<schema::Attempt> ls = RunMonteCarlo(config, AllComponents(), {1, nullptr});
  ASSERT_EQ(adaptive.size(), ls.size());
  int differ = 0;
  for (std::size_t i = 0; i < ls.size(); ++i) {
    if (ls[i].solve) {
      EXPECT_EQ(ls[i].solve->alpha, 2.0);
    }
    differ += adaptive[i].evaluation->error_m != ls[i].evaluation->error_m;
  }
  EXPECT_GT(differ, 0);
}

// An exception inside a task (here: a trigger that needs what a realization lacks would be one;
// an unknown trigger is another) must end in the one-line error, not std::terminate: the rows
// are checked before the loop, and errors in the loop are carried out of the parallel region.
TEST(MonteCarlo, AnUnbuildablePartIsAnInputErrorBeforeAnyTrial) {
  schema::ExperimentConfig config = SmallTable();
  config.rows[1].estimator.triggers = {"fixed_window", "no_such_trigger"};
  try {
    RunMonteCarlo(config, AllComponents(), {2, nullptr});
    FAIL() << "no error";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("row high: unknown trigger 'no_such_trigger'"), std::string::npos) << e.what();
  }
}

// A part that breaks its contract and throws inside a realization: the error leaves the parallel
// region as the exception it is (here the first task's), not as std::terminate.
TEST(MonteCarlo, AnExceptionInsideARealizationIsCarriedOutOfTheParallelLoop) {
  registry::Components components = eval::MakeComponentsWithOracles();
  struct Throwing : estimator::Solver {
    estimator::SolveResult Solve(std::span<const Eigen::Vector3d>, std::span<const double>) const override {
      throw std::runtime_error("solver exploded");
    }
  };
  components.solvers.Register("throwing", "breaks the contract", [](const std::string&, const registry::SolverContext&) {
    return std::make_unique<Throwing>();
  });
  schema::ExperimentConfig config = SmallTable();
  for (schema::RowConfig& row : config.rows) row.estimator.solver = "throwing";
  EXPECT_THROW(RunMonteCarlo(config, components, {2, nullptr}), std::runtime_error);
}

TEST(MonteCarlo, ThreadsComeFromTheOptionThenOmpNumThreads) {
  EXPECT_EQ(ResolveThreads(3), 3);
  ::setenv("OMP_NUM_THREADS", "5", 1);
  EXPECT_EQ(ResolveThreads(0), 5);
  ::unsetenv("OMP_NUM_THREADS");
  EXPECT_GE(ResolveThreads(0), 1);
}

}  // namespace
}  // namespace anchorbench::engine
