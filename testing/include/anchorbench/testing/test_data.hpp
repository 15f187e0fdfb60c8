#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/range_sample.hpp"

namespace anchorbench::testing {

// Tag positions and ranges for one anchor, generated for estimator tests.
struct AnchorData {
  Eigen::Vector3d p_world_anchor;
  double bias_m = 0.0;
  std::vector<Eigen::Vector3d> p_world_tag;
  std::vector<double> range_m;
};

// The tests' random numbers: std::mt19937_64 (a sequence the C++ standard fixes) with our own
// uniform and normal transforms, so the data are the same with every standard library; the
// estimator's tests need no simulator.
class TestRng {
 public:
  explicit TestRng(std::uint64_t seed) : engine_(seed) {}
  double Uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double Uniform(double low, double high) { return low + (high - low) * Uniform(); }
  double Normal() {  // Box-Muller, both values used
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u = 1.0 - Uniform();  // (0, 1]
    const double radius = std::sqrt(-2.0 * std::log(u));
    const double angle = 2.0 * std::numbers::pi * Uniform();
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }
  double Normal(double mean, double sigma) { return mean + sigma * Normal(); }
  bool Bernoulli(double probability) { return Uniform() < probability; }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// The median of `values` (taken by value: sorted here).
inline double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// One stream per test realization.
inline TestRng TestStream(std::uint64_t realization) { return TestRng(12345 + 0x9E3779B97F4A7C15ull * realization); }

// A vector of three draws, z first, then y, then x, each sequenced: draws written as the three
// arguments of one constructor would come in an order the compiler chooses (the tests' data were
// first made by GCC, which evaluates arguments right to left).
template <typename Draw>
Eigen::Vector3d Draw3(Draw draw) {
  const double z = draw(2);
  const double y = draw(1);
  const double x = draw(0);
  return Eigen::Vector3d(x, y, z);
}

// Uniform in the box [low, high] per axis.
inline Eigen::Vector3d UniformIn(TestRng& rng, const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  return Draw3([&](int axis) { return rng.Uniform(low[axis], high[axis]); });
}

// n tag positions uniformly in a box of half-size `spread_m` around `center`, ranges by Eq. (1)
// with bias and Gaussian noise.
inline AnchorData BoxData(TestRng& rng, int n, const Eigen::Vector3d& p_anchor,
                          const Eigen::Vector3d& center, double spread_m, double bias_m, double sigma_m) {
  AnchorData data{p_anchor, bias_m, {}, {}};
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d p = center + spread_m * UniformIn(rng, -Eigen::Vector3d::Ones(), Eigen::Vector3d::Ones());
    data.p_world_tag.push_back(p);
    data.range_m.push_back((p - p_anchor).norm() + bias_m + sigma_m * rng.Normal());
  }
  return data;
}

// A tag weaving in x-y at 1.5 m for 40 s at 10 Hz, with a vertical wobble of `wobble_m` (0: exactly
// flat), ranges by Eq. (1) with bias and Gaussian noise: the flat paths of the height tests.
inline AnchorData WeavingData(const Eigen::Vector3d& p_anchor, double bias_m, double wobble_m, double sigma_m,
                              std::uint64_t seed) {
  auto rng = TestStream(seed);
  AnchorData data{p_anchor, bias_m, {}, {}};
  for (int k = 0; k < 400; ++k) {
    const double t = 0.1 * k;
    const Eigen::Vector3d p(-10.0 + 0.5 * t, 3.0 * std::sin(0.4 * t), 1.5 + wobble_m * std::sin(0.9 * t));
    data.p_world_tag.push_back(p);
    data.range_m.push_back((p - p_anchor).norm() + bias_m + sigma_m * rng.Normal());
  }
  return data;
}

// A tag weaving past a wall anchor at 10 Hz for 120 s (range bias 0.1 m): the closest-point PDOP
// falls as the anchor is passed.
inline std::vector<estimator::RangeSample> PassBy(const Eigen::Vector3d& p_anchor, double sigma_m, std::uint64_t seed) {
  auto rng = TestStream(seed);
  std::vector<estimator::RangeSample> samples;
  for (int k = 0; k < 1200; ++k) {
    const double t = 0.1 * k;
    const Eigen::Vector3d p(-30.0 + 0.5 * t, 2.0 * std::sin(0.3 * t), 1.5 + 1.0 * std::sin(0.17 * t));
    samples.push_back({t, 0, 7, (p - p_anchor).norm() + 0.1 + sigma_m * rng.Normal(), p});
  }
  return samples;
}

}  // namespace anchorbench::testing
