#include "residual_arrays.hpp"

#include <algorithm>

namespace anchorbench::estimator::internal {

void ChunkResiduals::At(const SampleArrays& samples, Eigen::Index start, Eigen::Index size,
                        const Eigen::Vector4d& theta, bool with_directions) {
  if (size == 0) return;
  // The tag positions' coordinates, read in place with a stride (a Vector3d is 3 packed doubles).
  using Coordinates = Eigen::Map<const Eigen::ArrayXd, 0, Eigen::InnerStride<3>>;
  const double* first = samples.p[static_cast<std::size_t>(start)].data();
  ux = theta(0) - Coordinates(first, size);
  uy = theta(1) - Coordinates(first + 1, size);
  uz = theta(2) - Coordinates(first + 2, size);
  r = (ux.square() + uy.square() + uz.square()).sqrt();  // the distances, for now
  if (with_directions) {
    for (Eigen::Index k = 0; k < size; ++k) {
      // One division for the three directions; the anchor on the tag has none.
      const double inverse = r[k] > 1e-12 ? 1.0 / r[k] : 0.0;
      ux[k] *= inverse;
      uy[k] *= inverse;
      uz[k] *= inverse;
    }
  }
  r = (r + theta(3)) - Eigen::Map<const Eigen::ArrayXd>(samples.d.data() + start, size);  // Eq. (11), in RangeResidual's order
}

void NormalSums::Add(const Chunk& w, const ChunkResiduals& residuals) {
  auto add = [&](const Pair& wk, const Pair& x, const Pair& y, const Pair& z, const Pair& r) {
    const Pair wx = wk * x, wy = wk * y, wz = wk * z, wr = wk * r;
    xx_ += wx * x, xy_ += wx * y, xz_ += wx * z, yy_ += wy * y, yz_ += wy * z, zz_ += wz * z;
    sx_ += wx, sy_ += wy, sz_ += wz, sw_ += wk;
    gx_ += wx * r, gy_ += wy * r, gz_ += wz * r, gw_ += wr, ss_ += wr * r;
  };
  const Eigen::Index n = w.size();
  const Eigen::Index pairs = n / 2 * 2;
  for (Eigen::Index k = 0; k < pairs; k += 2) {
    add(w.segment<2>(k), residuals.ux.segment<2>(k), residuals.uy.segment<2>(k), residuals.uz.segment<2>(k),
        residuals.r.segment<2>(k));
  }
  if (pairs < n) {  // the odd one out (the last chunk only), in the first lane
    const Eigen::Index k = n - 1;
    add(Pair(w[k], 0.0), Pair(residuals.ux[k], 0.0), Pair(residuals.uy[k], 0.0), Pair(residuals.uz[k], 0.0),
        Pair(residuals.r[k], 0.0));
  }
}

void NormalSums::Finish(Eigen::Matrix4d* information, Eigen::Vector4d* gradient, double* weighted_squares) const {
  *information << xx_.sum(), xy_.sum(), xz_.sum(), sx_.sum(),  //
      xy_.sum(), yy_.sum(), yz_.sum(), sy_.sum(),              //
      xz_.sum(), yz_.sum(), zz_.sum(), sz_.sum(),              //
      sx_.sum(), sy_.sum(), sz_.sum(), sw_.sum();
  *gradient << gx_.sum(), gy_.sum(), gz_.sum(), gw_.sum();
  *weighted_squares = ss_.sum();
}

PassResult Pass(const SampleArrays& samples, const Eigen::Vector4d& theta, double kernel_scale_m,
                const PassRequest& request) {
  PassResult result;
  ChunkResiduals residuals;
  Chunk x;
  KernelArrays kernel;
  NormalSums sums;
  if (request.histogram) request.histogram->Clear();
  for (Eigen::Index start = 0; start < samples.size(); start += kChunk) {
    const Eigen::Index size = std::min<Eigen::Index>(kChunk, samples.size() - start);
    residuals.At(samples, start, size, theta, request.equations);
    x = residuals.r / kernel_scale_m;
    if (request.histogram) request.histogram->AddAll(x);
    if (!request.cost) continue;
    kernel.Evaluate(x, request.alpha);
    result.cost += kernel.rho().sum();
    if (request.equations) sums.Add(kernel.weight(), residuals);
  }
  if (request.equations) sums.Finish(&result.information, &result.gradient, &result.weighted_squares);
  return result;
}

}  // namespace anchorbench::estimator::internal
