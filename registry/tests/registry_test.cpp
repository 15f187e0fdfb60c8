// The registry as a caller owns it: its own parts beside the built-ins, validation against it.
#include "anchorbench/registry/components.hpp"

#include <gtest/gtest.h>

#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::registry {
namespace {

TEST(Components, CheckUsesTheCallersRegistriesIncludingTheirOwnParts) {
  Components components;
  RegisterBuiltins(components);
  schema::EstimatorConfig config;
  config.solver = "my_solver";
  std::string why;
  EXPECT_FALSE(components.Check(config, &why));
  EXPECT_NE(why.find("unknown solver 'my_solver'"), std::string::npos) << why;
  components.solvers.Register("my_solver", "LS only", [](const std::string&, const SolverContext& context) {
    return std::make_unique<estimator::DoubleDifferenceLsSolver>(context.options.ls);
  });
  EXPECT_TRUE(components.Check(config, &why)) << why;
  config.triggers = {"pdop_closest_point", "my_trigger"};
  EXPECT_FALSE(components.Check(config, &why));
  components.triggers.Register("my_trigger", "after 50 samples", [](const std::string&, const TriggerContext&) {
    return std::make_unique<estimator::SampleCountTrigger>(50);
  });
  EXPECT_TRUE(components.Check(config, &why)) << why;
  const auto chains = MakeChains(components, 3, config, 1);
  ASSERT_EQ(chains.size(), 2u);
  EXPECT_EQ(chains[1].anchor_id(), 3);
}

TEST(Components, SolversShareTheOwnersKernelTable) {
  Components components;
  RegisterBuiltins(components);
  estimator::AnchorSolverOptions options;
  const auto first = components.tables->Get(options.nls.truncation, options.nls.alpha_min);
  components.solvers.Create("lm_adaptive", {options, 0, components.tables.get()});
  EXPECT_EQ(components.tables->Get(options.nls.truncation, options.nls.alpha_min), first);
}

}  // namespace
}  // namespace anchorbench::registry
