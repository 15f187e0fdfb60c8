#include "anchorbench/engine/plan.hpp"

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/components.hpp"
#include "anchorbench/testing/small_table.hpp"

namespace anchorbench::engine {
namespace {

using testing::SmallTable;

// Every unit of every experiment in exactly one chunk, in order; chunks of the documented size.
TEST(Plan, ChunksHoldEveryUnitOnceInOrder) {
  std::vector<schema::ExperimentConfig> experiments;
  for (int realizations : {1, 6, 128, 300, 20000}) {
    experiments.push_back(SmallTable());
    experiments.back().realizations = realizations;
  }
  const Plan plan(experiments);
  long long units = 0;
  std::size_t c = 0;
  for (int e = 0; e < static_cast<int>(experiments.size()); ++e) {
    const int experiment_units = 2 * experiments[static_cast<std::size_t>(e)].realizations;
    const int size = std::min(kMaxChunkUnits, (experiment_units + kChunksPerExperiment - 1) / kChunksPerExperiment);
    for (int next = 0; next < experiment_units; ++c) {
      ASSERT_LT(c, plan.chunks().size());
      const ChunkSpan& span = plan.chunks()[c];
      EXPECT_EQ(span.experiment, e);
      EXPECT_EQ(span.first_unit, next);
      EXPECT_EQ(span.end_unit, std::min(next + size, experiment_units));
      next = span.end_unit;
    }
    units += experiment_units;
  }
  EXPECT_EQ(c, plan.chunks().size());
  EXPECT_EQ(plan.units(), units);
  EXPECT_EQ(plan.chunks().size(), 2u + 12u + 256u + 200u + 625u);  // 1 and 64 units a chunk at the ends
}

// A worker's copy, rebuilt from the texts, is the same plan; texts that do not match the identity
// they came with are refused.
TEST(Plan, ReadBackFromItsTextsItIsTheSamePlan) {
  schema::ExperimentConfig other = SmallTable();
  other.seed = 8;
  const Plan plan({SmallTable(), other});
  const Plan copy = PlanFromTexts(plan.texts(), plan.identity(), testing::AllComponents());
  EXPECT_EQ(copy.identity(), plan.identity());
  ASSERT_EQ(copy.chunks().size(), plan.chunks().size());
  EXPECT_EQ(copy.experiments()[1].seed, 8u);
  EXPECT_NE(Plan({SmallTable()}).identity(), plan.identity());
  EXPECT_THROW(PlanFromTexts(plan.texts(), Plan({SmallTable()}).identity(), testing::AllComponents()), schema::InputError);
}

}  // namespace
}  // namespace anchorbench::engine
