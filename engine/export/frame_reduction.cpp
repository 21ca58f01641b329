#include "export/frame_reduction.h"

#include <algorithm>
#include <stdexcept>

namespace ib::gltf {

namespace {

// The largest vertex distance between the blend of decoded frames i and j at frame f's time and
// the exact frame f.
double blendError(const Eigen::MatrixX2d& di, const Eigen::MatrixX2d& dj, double ti, double tj, double tf,
                  const Eigen::MatrixX2d& exact) {
  const double u = (tf - ti) / (tj - ti);
  return ((1 - u) * di + u * dj - exact).rowwise().norm().maxCoeff();
}

}  // namespace

FrameReduction reduceFrames(const std::vector<Eigen::MatrixX2d>& exact,
                            const std::function<Eigen::MatrixX2d(int frame)>& decoded, const std::vector<double>& times,
                            double maxError) {
  const int n = static_cast<int>(exact.size());
  if (n == 0 || times.size() != exact.size())
    throw std::invalid_argument("reduceFrames: needs one time per frame and at least one frame");
  if (!(maxError >= 0)) throw std::invalid_argument("reduceFrames: the bound must be >= 0");
  std::vector<Eigen::MatrixX2d> decodedFrames(n);
  for (int f = 0; f < n; ++f) decodedFrames[f] = decoded(f);
  FrameReduction reduction;
  auto ownError = [&](int f) { return (decodedFrames[f] - exact[f]).rowwise().norm().maxCoeff(); };
  int i = 0;
  reduction.kept.push_back(0);
  reduction.maxError = ownError(0);
  while (i < n - 1) {
    // The farthest j > i such that every frame strictly between is within the bound; j = i + 1
    // always qualifies (nothing between).
    int best = i + 1;
    double bestError = 0;
    for (int j = i + 2; j < n && maxError > 0; ++j) {
      double worst = 0;
      for (int f = i + 1; f < j && worst <= maxError; ++f)
        worst = std::max(worst, blendError(decodedFrames[i], decodedFrames[j], times[i], times[j], times[f], exact[f]));
      if (worst > maxError) break;
      best = j;
      bestError = worst;
    }
    reduction.kept.push_back(best);
    reduction.maxError = std::max({reduction.maxError, bestError, ownError(best)});
    i = best;
  }
  return reduction;
}

}  // namespace ib::gltf
