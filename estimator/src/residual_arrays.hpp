#pragma once

#include <span>

#include <Eigen/Core>

#include "anchorbench/estimator/robust_kernel.hpp"

namespace anchorbench::estimator::internal {

// The samples of one solve, as the caller holds them: the passes below read them a chunk at a time
// (the coordinates with a stride) into the chunk's arrays, and compute on those vectorized. No
// copy of the samples: a solve allocates nothing that grows with N.
struct SampleArrays {
  SampleArrays(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m)
      : p(p_world_tag), d(range_m) {}
  Eigen::Index size() const { return static_cast<Eigen::Index>(d.size()); }
  std::span<const Eigen::Vector3d> p;  // a view: a solve copies nothing per sample
  std::span<const double> d;
};

// The residuals of Eq. (11) of the samples [start, start + size) at theta = (p_A, gamma): the
// same values as RangeResidual (range_residual.hpp), to the bit (a test checks), and on request
// the unit vectors u_k from the tag to the anchor (zero with the anchor on the tag), so that the
// Jacobian rows are [u_k^T, 1].
struct ChunkResiduals {
  void At(const SampleArrays& samples, Eigen::Index start, Eigen::Index size, const Eigen::Vector4d& theta,
          bool with_directions);
  Chunk ux, uy, uz, r;
};

// sum w J J^T, sum w r J and sum w r^2, accumulated chunk by chunk over the even and the odd
// samples in the two lanes of an SSE2 packet, and added at the end.
class NormalSums {
 public:
  void Add(const Chunk& w, const ChunkResiduals& residuals);
  void Finish(Eigen::Matrix4d* information, Eigen::Vector4d* gradient, double* weighted_squares) const;

 private:
  using Pair = Eigen::Array2d;
  Pair xx_ = Pair::Zero(), xy_ = Pair::Zero(), xz_ = Pair::Zero(), yy_ = Pair::Zero(), yz_ = Pair::Zero(),
       zz_ = Pair::Zero(), sx_ = Pair::Zero(), sy_ = Pair::Zero(), sz_ = Pair::Zero(), sw_ = Pair::Zero(),
       gx_ = Pair::Zero(), gy_ = Pair::Zero(), gz_ = Pair::Zero(), gw_ = Pair::Zero(), ss_ = Pair::Zero();
};

// What one pass over all samples at one theta delivers, as asked.
struct PassRequest {
  double alpha = 2.0;     // the kernel's shape
  bool cost = true;       // sum of rho(r/c) (with the kernel); false: residuals only
  bool equations = false;  // the normal equations (needs the cost's kernel)
  AlphaSelector* histogram = nullptr;  // filled with r/c (cleared first)
};
struct PassResult {
  double cost = 0.0;
  Eigen::Matrix4d information = Eigen::Matrix4d::Zero();
  Eigen::Vector4d gradient = Eigen::Vector4d::Zero();
  double weighted_squares = 0.0;
};

// One pass over the samples, a chunk at a time: residuals, then the kernel and the sums on the
// chunk while it is in the cache. O(N), nothing allocated.
PassResult Pass(const SampleArrays& samples, const Eigen::Vector4d& theta, double kernel_scale_m,
                const PassRequest& request);

}  // namespace anchorbench::estimator::internal
