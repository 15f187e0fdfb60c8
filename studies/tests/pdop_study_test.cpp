#include "anchorbench/studies/pdop_study.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "anchorbench/eval/oracles.hpp"
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

TEST(PdopStudy, IdenticalForAnyThreadCountAndConsistent) {
  const schema::PdopStudy one = RunPdopStudy(OneAnchor(), AllComponents(), 10, 1);
  const schema::PdopStudy two = RunPdopStudy(OneAnchor(), AllComponents(), 10, 2);
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
  const schema::PdopStudy study = RunPdopStudy(OneAnchor(), AllComponents(), 10, 2);
  // The last checkpoint of each run has all of the anchor's data: a tunnel pass at 1 m/s.
  for (std::size_t i = 0; i + 1 < study.checkpoints.size(); ++i) {
    const schema::PdopCheckpoint& c = study.checkpoints[i];
    if (study.checkpoints[i + 1].realization == c.realization) continue;
    ASSERT_TRUE(c.nls_error_m.has_value());
    EXPECT_LT(*c.nls_error_m, 1.0) << "realization " << c.realization;
  }
}

}  // namespace
}  // namespace anchorbench::studies
