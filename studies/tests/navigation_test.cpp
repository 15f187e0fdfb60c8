#include "anchorbench/studies/navigation.hpp"

#include <gtest/gtest.h>

#include "anchorbench/studies/navigation_lines.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/components.hpp"
#include "anchorbench/testing/small_table.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::studies {
namespace {

using engine::ChunkStore;
using engine::RecordJournal;

using testing::AllComponents;

schema::ExperimentConfig Navigated() {
  schema::ExperimentConfig config = testing::SmallTable();
  config.realizations = 3;
  config.navigation.emplace();
  return config;
}

TEST(Navigation, EveryTriggerAndBothBaselinesForEachRowAndRealizationTheSameOnAnyThreads) {
  const schema::ExperimentConfig config = Navigated();
  const std::vector<NavigationRecord> one = RunNavigation(config, AllComponents(), 1);
  const std::vector<NavigationRecord> two = RunNavigation(config, AllComponents(), 3);
  const std::size_t methods = config.estimator.triggers.size() + 2;
  ASSERT_EQ(one.size(), 2 * 3 * methods);
  ASSERT_EQ(two.size(), one.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].method, two[i].method);
    EXPECT_EQ(one[i].outcome.rmse_m, two[i].outcome.rmse_m) << i;  // bit for bit
    EXPECT_EQ(one[i].row, static_cast<int>(i / (3 * methods)));
  }
  EXPECT_EQ(one[methods - 2].method, kTrueAnchors);
  EXPECT_EQ(one[methods - 1].method, kNoAnchors);
  for (std::size_t unit = 0; unit < 6; ++unit) {
    const NavigationRecord& floor = one[unit * methods + methods - 2];
    const NavigationRecord& drift = one[unit * methods + methods - 1];
    EXPECT_LT(floor.outcome.rmse_m, drift.outcome.rmse_m);
    EXPECT_EQ(floor.outcome.fix_share, 1.0);
    EXPECT_EQ(drift.outcome.fix_share, 0.0);
  }
}

// A run resumed from its journal: the units that read back are taken, a unit whose checksum fits
// but whose values no run writes is refused and computed again, and the records are the
// uninterrupted run's, bit for bit.
TEST(Navigation, AResumedRunTakesItsJournalsUnitsAndGivesTheUninterruptedRecords) {
  const testing::TempDir dir("navigation_journal");
  const schema::ExperimentConfig config = Navigated();
  const std::vector<NavigationRecord> whole = RunNavigation(config, AllComponents(), 2);
  const std::size_t methods = config.estimator.triggers.size() + 2;
  const auto unit_records = [&](std::size_t unit) {
    return std::vector<NavigationRecord>(whole.begin() + static_cast<long>(unit * methods),
                                         whole.begin() + static_cast<long>((unit + 1) * methods));
  };
  {
    RecordJournal killed(dir.path() / "out", "navigate", 6, ChunkStore::Mode::kFresh);
    killed.Append(1, NavigationUnitText(unit_records(1)));
    std::vector<NavigationRecord> forged = unit_records(4);
    forged[0].outcome.fix_share = 2.0;  // no run writes it; the block's checksum is made to fit
    killed.Append(4, NavigationUnitText(forged));
  }
  RecordJournal journal(dir.path() / "out", "navigate", 6, ChunkStore::Mode::kResume);
  const std::vector<NavigationRecord> resumed = RunNavigation(config, AllComponents(), 2, {}, {}, &journal);
  EXPECT_EQ(journal.unreadable(), 1);
  EXPECT_NE(journal.first_unreadable().find("fix share"), std::string::npos) << journal.first_unreadable();
  ASSERT_EQ(resumed.size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(NavigationRecordFields(resumed[i]), NavigationRecordFields(whole[i])) << i;
  }
}

TEST(Navigation, AConfigWithoutANavigationSectionIsRefused) {
  EXPECT_THROW(RunNavigation(testing::SmallTable(), AllComponents(), 1), schema::InputError);
}

}  // namespace
}  // namespace anchorbench::studies
