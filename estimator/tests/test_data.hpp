#pragma once

#include <vector>

#include <Eigen/Core>

#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::testing {

// Tag positions and ranges for one anchor, generated for estimator tests.
struct AnchorData {
  Eigen::Vector3d p_world_anchor;
  double bias_m = 0.0;
  std::vector<Eigen::Vector3d> p_world_tag;
  std::vector<double> range_m;
};

inline sim::RandomStream TestStream(std::uint64_t realization) {
  return sim::RandomStream(12345, realization, sim::StreamId::kSolver);
}

// n tag positions uniformly in a box of half-size `spread_m` around `center`, ranges by Eq. (1)
// with bias and Gaussian noise.
inline AnchorData BoxData(sim::RandomStream& rng, int n, const Eigen::Vector3d& p_anchor,
                          const Eigen::Vector3d& center, double spread_m, double bias_m, double sigma_m) {
  AnchorData data{p_anchor, bias_m, {}, {}};
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d p = center + spread_m * Eigen::Vector3d(rng.Uniform(-1, 1), rng.Uniform(-1, 1),
                                                                   rng.Uniform(-1, 1));
    data.p_world_tag.push_back(p);
    data.range_m.push_back((p - p_anchor).norm() + bias_m + sigma_m * rng.Normal());
  }
  return data;
}

}  // namespace anchorbench::testing
