#pragma once

#include <array>
#include <cstdint>

namespace anchorbench::sim {

// The simulator's random streams. Each noise source has its own stream (after open_vins), so a new
// realization changes the noise, and changing one source leaves the others untouched. Stream ids
// belong to whoever draws them: the simulator uses 1 to 7 and 16 to 18; other layers pick ids from
// kFirstFreeStreamId up and name them where they draw (schema/random_streams.hpp: solver seeds 8, bootstrap 9).
enum class StreamId : std::uint32_t {
  kLayout = 1,      // anchor positions
  kTrajectory = 2,  // trajectory shape and kind
  kBias = 3,        // per-anchor constant range bias
  kRangeNoise = 4,  // Gaussian range noise eta (one sub-stream per tag and anchor)
  kOutlier = 5,     // outlier occurrence and magnitude (one sub-stream per tag and anchor)
  kPositionNoise = 6,
  kDropout = 7,
  // The radio biases (range_model.hpp), added after the ids above were given away: 16 and up.
  kAntennaPattern = 16,  // one sub-stream per anchor (its id) and per tag (1 << 16 | tag)
  kLinkOffset = 17,      // one sub-stream per tag and anchor
  kRangeScale = 18,      // one sub-stream per anchor
};
constexpr std::uint32_t kFirstFreeStreamId = 8;  // 8 to 15 and 19 up are free

// Counter-based generator: Philox4x32-10 (Salmon et al., SC'11). The key is the seed; the counter
// is (block index, stream << 24 ^ sub-stream, realization), so any (seed, realization, stream,
// sub-stream) is an independent sequence that any thread can produce without shared state.
// Stream ids take 8 bits and sub-streams 24. Uniform and normal transforms are our own, so
// results do not depend on the standard library's distributions.
class RandomStream {
 public:
  static constexpr std::uint32_t kMaxStream = 0xFF;
  static constexpr std::uint32_t kMaxSubstream = 0xFFFFFF;

  RandomStream(std::uint64_t seed, std::uint64_t realization, std::uint32_t stream, std::uint32_t substream = 0);
  RandomStream(std::uint64_t seed, std::uint64_t realization, StreamId stream, std::uint32_t substream = 0)
      : RandomStream(seed, realization, static_cast<std::uint32_t>(stream), substream) {}

  std::uint32_t NextU32();
  std::uint64_t NextU64();
  double Uniform();                      // [0, 1), 53 random bits
  double Uniform(double low, double high);
  double Normal();                       // standard normal (Box-Muller)
  double Normal(double mean, double sigma) { return mean + sigma * Normal(); }
  bool Bernoulli(double probability) { return Uniform() < probability; }

 private:
  void Refill();

  std::array<std::uint32_t, 2> key_;
  std::array<std::uint32_t, 4> counter_;
  std::array<std::uint32_t, 4> block_{};
  int next_word_ = 4;
  double spare_normal_ = 0.0;
  bool has_spare_normal_ = false;
};

// The raw Philox4x32-10 bijection, exposed for the known-answer test.
std::array<std::uint32_t, 4> Philox4x32(std::array<std::uint32_t, 4> counter, std::array<std::uint32_t, 2> key);

}  // namespace anchorbench::sim
