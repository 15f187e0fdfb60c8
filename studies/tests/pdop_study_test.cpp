#include "anchorbench/studies/pdop_study.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/components.hpp"

namespace anchorbench::studies {
namespace {

using anchorbench::testing::AllComponents;

schema::ExperimentConfig OneAnchor() {
  schema::ExperimentConfig config;
  config.realizations = 6;
  config.scenario.tunnel.length_m = 60.0;
  config.scenario.tunnel.num_anchors = 1;
  config.scenario.trajectory.speed_mps = 1.0;
  config.scenario.ranging.sigma_range_m = 0.15;
  config.estimator.filter.consistency.tau_m = 0.3;
  config.estimator.solver_options.nls.kernel_scale_m = 0.15;
  return config;
}

// The study on `threads` threads, a checkpoint every 10 samples.
schema::PdopStudy Study(int threads) {
  schema::ExperimentConfig config = OneAnchor();
  config.pdop_study = schema::PdopStudyConfig{10, 10.0};
  return JoinPdopStudy(RunPdopStudy(config, AllComponents(), threads));
}

TEST(PdopStudy, IdenticalForAnyThreadCountAndConsistent) {
  const schema::PdopStudy one = Study(1);
  const schema::PdopStudy two = Study(2);
  ASSERT_EQ(one.checkpoints.size(), two.checkpoints.size());
  ASSERT_GT(one.checkpoints.size(), 6u * 10u);
  for (std::size_t i = 0; i < one.checkpoints.size(); ++i) {
    const schema::PdopCheckpoint& a = one.checkpoints[i];
    const schema::PdopCheckpoint& b = two.checkpoints[i];
    EXPECT_EQ(a.n, b.n);
    for (int m = 0; m < 4; ++m) {
      EXPECT_TRUE(a.pdop[m] == b.pdop[m] || (std::isnan(a.pdop[m]) && std::isnan(b.pdop[m])));
    }
    EXPECT_EQ(a.n % 10, 0);  // a checkpoint every 10 accepted samples
    EXPECT_FALSE(std::isnan(a.pdop[0]));
    // With the bias estimated, only the spread of directions counts: never below the true PDOP.
    if (std::isfinite(a.bias_aware_dop)) {
      EXPECT_GE(a.bias_aware_dop, a.pdop[static_cast<int>(schema::PdopMethod::kTrue)] * (1.0 - 1e-9));
    }
  }
  EXPECT_EQ(one.anchors, 6);  // one anchor per realization, counted from the scenarios
  ASSERT_EQ(one.certified.size(), 6u);  // the certified chain's outcome for every anchor
  for (std::size_t i = 0; i < one.certified.size(); ++i) {
    const schema::CertifiedOutcome& a = one.certified[i];
    const schema::CertifiedOutcome& b = two.certified[i];
    EXPECT_EQ(a.status, b.status);
    EXPECT_EQ(a.n, b.n);
    EXPECT_EQ(a.error_m, b.error_m);
    if (a.error_m) {
      EXPECT_TRUE(a.t_s.has_value());
      EXPECT_LT(*a.error_m, 0.75) << "certified within D, realization " << a.realization;
    }
  }
  EXPECT_EQ(one.stats.below, two.stats.below);
  EXPECT_LE(one.stats.below, one.stats.samples);
  EXPECT_LE(one.stats.ideal_below_precondition, one.stats.ideal_samples_precondition);
  EXPECT_LE(one.stats.ideal_samples_precondition, one.stats.samples);
}

TEST(PdopStudy, EstimatesConvergeToTheAnchor) {
  const schema::PdopStudy study = Study(2);
  // The last checkpoint of each run has all of the anchor's data: a tunnel pass at 1 m/s.
  for (std::size_t i = 0; i + 1 < study.checkpoints.size(); ++i) {
    const schema::PdopCheckpoint& c = study.checkpoints[i];
    if (study.checkpoints[i + 1].realization == c.realization) continue;
    ASSERT_TRUE(c.nls_error_m.has_value());
    EXPECT_LT(*c.nls_error_m, 1.0) << "realization " << c.realization;
  }
}

// A realization's record as the journal and a shard keep it: the same text read back, and lines of
// another realization, a kind no run writes, or a unit cut before its statistics refused.
TEST(PdopStudy, AUnitsTextReadsBackAndRefusesWhatNoRunWrites) {
  schema::ExperimentConfig config = OneAnchor();
  config.pdop_study = schema::PdopStudyConfig{25, 10.0};
  const engine::UnitRecords<schema::PdopStudy> units = PdopStudyUnits(config, AllComponents());
  ASSERT_EQ(units.units, 6);
  const std::string text = units.text(units.compute(2));
  const engine::UnitPlace place{"journal.csv", 7};
  EXPECT_EQ(units.text(units.read(text, place, 2)), text);
  const schema::PdopStudy back = units.read(text, place, 2).front();
  EXPECT_GT(back.checkpoints.size(), 2u);
  EXPECT_EQ(back.checkpoints.front().n, 25);
  EXPECT_EQ(back.anchors, 1);
  auto refusal = [&](const std::string& edited, int realization) {
    try {
      units.read(edited, place, realization);
    } catch (const schema::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal(text, 3).find("journal.csv:"), std::string::npos);
  const std::size_t last_line = text.rfind('\n', text.size() - 2) + 1;
  EXPECT_NE(refusal(text.substr(0, last_line), 2).find("no statistics line"), std::string::npos);
  EXPECT_NE(refusal("bogus" + text.substr(text.find(',')), 2).find("not a kind of line"), std::string::npos);
  std::string negative = text;
  negative.replace(negative.find(",25,"), 4, ",-25,");
  EXPECT_NE(refusal(negative, 2), "accepted");
}

}  // namespace
}  // namespace anchorbench::studies
