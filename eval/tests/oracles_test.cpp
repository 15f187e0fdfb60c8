#include "anchorbench/eval/oracles.hpp"

#include <stdexcept>

#include <gtest/gtest.h>

#include "anchorbench/eval/attempt_evaluation.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::eval {
namespace {

const Eigen::Vector3d kAnchor(0, 4, 3);

schema::EstimatorConfig Unfiltered() {
  schema::EstimatorConfig config;
  config.filter.kind = "none";
  return config;
}

// The sample index where `trigger` fires, and where `measure` of the samples so far at the true
// anchor first drops below `threshold` (at or after min_samples = 20).
template <typename Measure>
std::pair<int, int> FiredAndExpected(const std::string& trigger, const schema::EstimatorConfig& config,
                                     Measure measure, double threshold) {
  const auto samples = testing::PassBy(kAnchor, 0.05, 2);
  const registry::Components components = MakeComponentsWithOracles();
  estimator::AnchorInitializer initializer = registry::MakeInitializer(components, 7, config, trigger, 0, kAnchor);
  int fired = -1;
  for (std::size_t i = 0; i < samples.size() && fired < 0; ++i) {
    if (initializer.Feed(samples[i]).event) fired = static_cast<int>(i);
  }
  int expected = -1;
  std::vector<Eigen::Vector3d> p;
  for (std::size_t i = 0; i < samples.size() && expected < 0; ++i) {
    p.push_back(samples[i].p_world_tag);
    if (p.size() >= 20 && measure(p, kAnchor) < threshold) expected = static_cast<int>(i);
  }
  return {fired, expected};
}

// The oracle fires on the first sample (at or after min_samples) where Eq. (3) at the true anchor
// over the samples so far drops below the threshold.
TEST(Oracles, TruePdopFiresWhereTheTruePdopFirstDropsBelowTheThreshold) {
  const auto [fired, expected] = FiredAndExpected("pdop_true", Unfiltered(), TruePdop, 1.0);
  ASSERT_GE(expected, 0);
  EXPECT_EQ(fired, expected);
}

// dop4_true: the same with the bias-aware DOP, which is never below the PDOP.
TEST(Oracles, TrueBiasAwareDopFiresWhereItFirstDropsBelowItsThreshold) {
  schema::EstimatorConfig config = Unfiltered();
  config.trigger.bias_aware_threshold = 1.2;
  const auto [fired, expected] = FiredAndExpected("dop4_true", config, BiasAwareDop, 1.2);
  ASSERT_GE(expected, 0);
  EXPECT_EQ(fired, expected);
}

// Before it fires, each oracle says why it waits: its true DOP against the threshold.
TEST(Oracles, WhyNotIsTheTrueDopAgainstTheThreshold) {
  const auto samples = testing::PassBy(kAnchor, 0.05, 2);
  const registry::Components components = MakeComponentsWithOracles();
  for (const std::string trigger : {"pdop_true", "dop4_true"}) {
    estimator::AnchorInitializer initializer = registry::MakeInitializer(components, 7, Unfiltered(), trigger, 0, kAnchor);
    std::vector<Eigen::Vector3d> p;
    for (std::size_t i = 0; i < 100; ++i) {
      initializer.Feed(samples[i]);
      p.push_back(samples[i].p_world_tag);
    }
    ASSERT_FALSE(initializer.initialized()) << trigger;
    const std::optional<estimator::Judgement> why = initializer.why_not();
    ASSERT_TRUE(why.has_value());
    EXPECT_EQ(why->blocked_by, trigger);
    EXPECT_DOUBLE_EQ(why->value, trigger == "pdop_true" ? TruePdop(p, kAnchor) : BiasAwareDop(p, kAnchor));
    EXPECT_GE(why->value, why->limit);
  }
}

TEST(Oracles, WithoutTheTruthTheOracleIsRefusedWithTheReason) {
  const registry::Components components = MakeComponentsWithOracles();
  try {
    registry::MakeInitializer(components, 7, Unfiltered(), "pdop_true", 0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("trigger 'pdop_true': needs the true anchor position"), std::string::npos)
        << e.what();
  }
}

TEST(AttemptEvaluation, ErrorsAndDopsAgainstTheTruth) {
  auto rng = testing::TestStream(9);
  const auto data = testing::BoxData(rng, 40, kAnchor, Eigen::Vector3d(6, 1, 1), 4.0, 0.2, 0.0);
  estimator::SolveResult estimate;
  estimate.p_world_anchor = kAnchor + Eigen::Vector3d(0.3, 0.0, -0.4);
  estimate.bias_m = 0.25;
  const schema::AttemptEvaluation initialized = Evaluate(data.p_world_tag, &estimate, {kAnchor, 0.2});
  EXPECT_DOUBLE_EQ(*initialized.error_m, 0.5);  // a 3-4-5 triangle, in decimetres
  EXPECT_NEAR(*initialized.bias_error_m, 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(initialized.pdop_true, TruePdop(data.p_world_tag, kAnchor));
  EXPECT_DOUBLE_EQ(*initialized.bias_aware_dop, BiasAwareDop(data.p_world_tag, kAnchor));
  const schema::AttemptEvaluation missed = Evaluate(data.p_world_tag, nullptr, {kAnchor, std::nullopt});
  EXPECT_FALSE(missed.error_m || missed.error_xyz_m || missed.bias_error_m);
}

}  // namespace
}  // namespace anchorbench::eval
