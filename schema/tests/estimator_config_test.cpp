#include "anchorbench/schema/estimator_config.hpp"

#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

namespace anchorbench::schema {
namespace {

TEST(EstimatorConfig, ValidationNamesTheKey) {
  EstimatorConfig config;
  std::string why;
  EXPECT_TRUE(config.IsValid(&why)) << why;
  config.filter.ransac.subset_size = 200;
  config.filter.ransac.outlier_fraction = 0.99;  // (0.01)^200 underflows: no number of subsets suffices
  EXPECT_TRUE(config.IsValid(&why)) << why;      // the minimal scheme counts its draws from the data
  config.filter.ransac.scheme = estimator::RansacScheme::kFullSolve;
  EXPECT_FALSE(config.IsValid(&why));
  EXPECT_EQ(why.rfind("subset_size", 0), 0u) << why;
  config = {};
  config.triggers.clear();
  EXPECT_FALSE(config.IsValid(&why));
}

// A prior from a reference takes the anchor's reference height plus the offset, and refuses an
// anchor without one; a fixed prior takes z_m plus the offset; a disabled one gives none.
TEST(HeightPriorConfig, GivesEachAnchorItsPrior) {
  HeightPriorConfig config;
  EXPECT_FALSE(config.For(1, std::nullopt).has_value());
  config.enabled = true;
  config.z_m = 2.0;
  config.offset_m = 0.5;
  ASSERT_TRUE(config.For(1, std::nullopt).has_value());
  EXPECT_EQ(config.For(1, std::nullopt)->z_world_m, 2.5);
  config.from_reference = true;
  EXPECT_EQ(config.For(1, Eigen::Vector3d(0, 0, 4))->z_world_m, 4.5);
  EXPECT_THROW(config.For(1, std::nullopt), std::invalid_argument);
  std::string why;
  config.offset_m = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(config.IsValid(&why));
}

}  // namespace
}  // namespace anchorbench::schema
