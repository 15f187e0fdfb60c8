#include "anchorbench/sim/random_stream.hpp"

#include <cmath>
#include <numbers>

namespace anchorbench::sim {

std::array<std::uint32_t, 4> Philox4x32(std::array<std::uint32_t, 4> c, std::array<std::uint32_t, 2> k) {
  constexpr std::uint64_t kM0 = 0xD2511F53u;
  constexpr std::uint64_t kM1 = 0xCD9E8D57u;
  constexpr std::uint32_t kW0 = 0x9E3779B9u;
  constexpr std::uint32_t kW1 = 0xBB67AE85u;
  for (int round = 0; round < 10; ++round) {
    const std::uint64_t p0 = kM0 * c[0];
    const std::uint64_t p1 = kM1 * c[2];
    c = {static_cast<std::uint32_t>(p1 >> 32) ^ c[1] ^ k[0], static_cast<std::uint32_t>(p1),
         static_cast<std::uint32_t>(p0 >> 32) ^ c[3] ^ k[1], static_cast<std::uint32_t>(p0)};
    k[0] += kW0;
    k[1] += kW1;
  }
  return c;
}

// Ids beyond their bits are masked rather than allowed to spill into each other's bits.
RandomStream::RandomStream(std::uint64_t seed, std::uint64_t realization, std::uint32_t stream, std::uint32_t substream)
    : key_{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)},
      counter_{0u, ((stream & kMaxStream) << 24) ^ (substream & kMaxSubstream), static_cast<std::uint32_t>(realization),
               static_cast<std::uint32_t>(realization >> 32)} {}

void RandomStream::Refill() {
  block_ = Philox4x32(counter_, key_);
  ++counter_[0];  // 2^32 blocks (2^34 words) per stream
  next_word_ = 0;
}

std::uint32_t RandomStream::NextU32() {
  if (next_word_ == 4) Refill();
  return block_[next_word_++];
}

std::uint64_t RandomStream::NextU64() {
  const std::uint64_t high = NextU32();
  return (high << 32) | NextU32();
}

double RandomStream::Uniform() { return static_cast<double>(NextU64() >> 11) * 0x1.0p-53; }

double RandomStream::Uniform(double low, double high) { return low + (high - low) * Uniform(); }

double RandomStream::Normal() {
  if (has_spare_normal_) {
    has_spare_normal_ = false;
    return spare_normal_;
  }
  const double u1 = 1.0 - Uniform();  // (0, 1]: log is finite
  const double u2 = Uniform();
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  spare_normal_ = radius * std::sin(angle);
  has_spare_normal_ = true;
  return radius * std::cos(angle);
}

}  // namespace anchorbench::sim
