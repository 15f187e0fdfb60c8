#include "anchorbench/io/format.hpp"

#include <limits>

#include <gtest/gtest.h>

namespace anchorbench::io {
namespace {

TEST(Format, ATablesCellIsFixedOrADashWhereThereIsNoValue) {
  EXPECT_EQ(FormatFixed(0.12345, 3), "0.123");
  EXPECT_EQ(FormatFixed(std::numeric_limits<double>::infinity(), 3), "-");
  EXPECT_EQ(FormatFixed(std::optional<double>(2.5), 1), "2.5");
  EXPECT_EQ(FormatFixed(std::optional<double>(), 1), "-");
}

TEST(Format, AnIntervalFollowsItsValueOrIsNothing) {
  EXPECT_EQ(FormatInterval(0.1, 0.25, 2), " [0.10, 0.25]");
  EXPECT_EQ(FormatInterval(std::nullopt, std::nullopt, 2), "");
  EXPECT_EQ(FormatInterval(0.1, std::nullopt, 2), "");
  EXPECT_EQ(FormatWithInterval(0.25, 0.1, 0.4, 2), "0.25 [0.10, 0.40]");
  EXPECT_EQ(FormatWithInterval(0.25, std::nullopt, std::nullopt, 2), "0.25");
  EXPECT_EQ(FormatWithInterval(std::nullopt, 0.1, 0.4, 2), "-");
}

}  // namespace
}  // namespace anchorbench::io
