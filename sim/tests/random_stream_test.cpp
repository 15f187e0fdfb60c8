#include "anchorbench/sim/random_stream.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace anchorbench::sim {
namespace {

// Known-answer vectors of Philox4x32-10 from the Random123 distribution (kat_vectors).
TEST(Philox, KnownAnswers) {
  EXPECT_EQ(Philox4x32({0, 0, 0, 0}, {0, 0}),
            (std::array<std::uint32_t, 4>{0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u}));
  EXPECT_EQ(Philox4x32({0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu}, {0xffffffffu, 0xffffffffu}),
            (std::array<std::uint32_t, 4>{0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu}));
}

TEST(RandomStream, SameKeySameSequenceDifferentKeyDifferentSequence) {
  RandomStream a(42, 3, StreamId::kRangeNoise, 5), b(42, 3, StreamId::kRangeNoise, 5);
  RandomStream other_realization(42, 4, StreamId::kRangeNoise, 5);
  RandomStream other_stream(42, 3, StreamId::kOutlier, 5);
  RandomStream other_substream(42, 3, StreamId::kRangeNoise, 6);
  int same_realization = 0, same_stream = 0, same_substream = 0;
  for (int i = 0; i < 1000; ++i) {
    const std::uint64_t x = a.NextU64();
    EXPECT_EQ(x, b.NextU64());
    same_realization += x == other_realization.NextU64();
    same_stream += x == other_stream.NextU64();
    same_substream += x == other_substream.NextU64();
  }
  EXPECT_EQ(same_realization + same_stream + same_substream, 0);
}

TEST(RandomStream, UniformAndNormalMoments) {
  RandomStream rng(7, 0, kFirstFreeStreamId);
  constexpr int kN = 200000;
  double sum_u = 0, sum_z = 0, sum_z2 = 0, sum_z4 = 0, min_u = 1, max_u = 0;
  for (int i = 0; i < kN; ++i) {
    const double u = rng.Uniform();
    min_u = std::min(min_u, u);
    max_u = std::max(max_u, u);
    sum_u += u;
    const double z = rng.Normal();
    sum_z += z;
    sum_z2 += z * z;
    sum_z4 += z * z * z * z;
  }
  EXPECT_GE(min_u, 0.0);
  EXPECT_LT(max_u, 1.0);
  // Standard errors: uniform mean 0.29/sqrt(N) = 6.5e-4; normal mean 2.2e-3, variance 3.2e-3.
  EXPECT_NEAR(sum_u / kN, 0.5, 4e-3);
  EXPECT_NEAR(sum_z / kN, 0.0, 1e-2);
  EXPECT_NEAR(sum_z2 / kN, 1.0, 1.5e-2);
  EXPECT_NEAR(sum_z4 / kN, 3.0, 0.1);  // Gaussian kurtosis
}

}  // namespace
}  // namespace anchorbench::sim
