#pragma once
// The benchmarks' shared data: a tunnel-like pass by a wall anchor at p_A = (0, 4, 3) m with a
// range bias of 0.2 m, sigma_d = 0.1 m and NLOS outliers of +1..10 m (5% unless asked), N samples
// over 60 m.

#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::bench {

struct PassByAnchor {
  Eigen::Vector3d p_world_anchor{0.0, 4.0, 3.0};
  double bias_m = 0.2;
  std::vector<Eigen::Vector3d> p_world_tag;
  std::vector<double> range_m;
};

inline PassByAnchor MakePassByAnchor(std::size_t n, double outlier_share = 0.05) {
  sim::RandomStream rng(1, 0, sim::kFirstFreeStreamId);
  PassByAnchor data;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 60.0 * static_cast<double>(k) / static_cast<double>(n);
    const Eigen::Vector3d p(-30.0 + t, 2.0 * std::sin(0.3 * t), 1.5 + std::sin(0.17 * t));
    const double noise_m = 0.1 * rng.Normal();
    double d = (p - data.p_world_anchor).norm() + data.bias_m + noise_m;
    if (rng.Uniform() < outlier_share) d += rng.Uniform(1.0, 10.0);
    data.p_world_tag.push_back(p);
    data.range_m.push_back(d);
  }
  return data;
}

}  // namespace anchorbench::bench
