#include "animation/frame_changes.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ib {

namespace {

double meshArea(const Multimesh& mesh, const Eigen::MatrixX2d& x) {
  double sum = 0;
  for (const Triangle& t : mesh.triangles()) sum += 0.5 * edgeMatrix(x, t).determinant();
  return sum;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + middle, values.end());
  if (values.size() % 2 == 1) return values[middle];
  const double upper = values[middle];
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + middle));
}

int heldCount(const AnimationFrame& frame) {
  return static_cast<int>(std::count(frame.heldPairs.begin(), frame.heldPairs.end(), 1));
}

}  // namespace

std::vector<char> silhouetteMask(const Multimesh& mesh, const Eigen::MatrixX2d& x, const Eigen::Vector2d& origin,
                                 int width, int height) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("silhouetteMask: empty grid");
  std::vector<char> mask(static_cast<size_t>(width) * height, 0);
  for (const Triangle& t : mesh.triangles()) {
    Eigen::Vector2d p[3];
    for (int c = 0; c < 3; ++c) p[c] = x.row(t[c]).transpose() - origin;
    const double minX = std::min({p[0].x(), p[1].x(), p[2].x()}), maxX = std::max({p[0].x(), p[1].x(), p[2].x()});
    const double minY = std::min({p[0].y(), p[1].y(), p[2].y()}), maxY = std::max({p[0].y(), p[1].y(), p[2].y()});
    const int x0 = std::max(0, static_cast<int>(std::ceil(minX - 0.5))), x1 = std::min(width - 1, static_cast<int>(std::floor(maxX - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(minY - 0.5))), y1 = std::min(height - 1, static_cast<int>(std::floor(maxY - 0.5)));
    // Edge functions: a centre is inside when all three have one sign (either orientation, so an
    // inverted triangle covers its pixels too). A centre within 1e-9 px of an edge counts as on
    // it, for both triangles that share it: their rounded edge functions need not be opposite.
    const auto edge = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, double cx, double cy) {
      const double e = (b.x() - a.x()) * (cy - a.y()) - (b.y() - a.y()) * (cx - a.x());
      return std::abs(e) <= 1e-9 * (b - a).norm() ? 0.0 : e;
    };
    for (int py = y0; py <= y1; ++py)
      for (int px = x0; px <= x1; ++px) {
        const double cx = px + 0.5, cy = py + 0.5;
        const double e0 = edge(p[0], p[1], cx, cy), e1 = edge(p[1], p[2], cx, cy), e2 = edge(p[2], p[0], cx, cy);
        if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0)) mask[static_cast<size_t>(py) * width + px] = 1;
      }
  }
  return mask;
}

std::vector<SegmentChanges> segmentChanges(const Multimesh& mesh, const Timeline& timeline,
                                           const std::vector<AnimationFrame>& frames) {
  std::vector<SegmentChanges> out;
  if (frames.size() < 2) return out;
  // One grid for every frame: the box of all frames and keys, 2 px of margin.
  Eigen::Vector2d low = frames.front().x.colwise().minCoeff().transpose(), high = frames.front().x.colwise().maxCoeff().transpose();
  const auto grow = [&](const Eigen::MatrixX2d& x) {
    low = low.cwiseMin(x.colwise().minCoeff().transpose());
    high = high.cwiseMax(x.colwise().maxCoeff().transpose());
  };
  for (const AnimationFrame& f : frames) grow(f.x);
  for (int k = 0; k < mesh.keyCount(); ++k) grow(mesh.keyPositions(k));
  if (!low.allFinite() || !high.allFinite()) throw std::invalid_argument("segmentChanges: a frame is not finite");
  const Eigen::Vector2d origin = low.array().floor() - 2;
  const int width = static_cast<int>(std::ceil(high.x() - origin.x())) + 2;
  const int height = static_cast<int>(std::ceil(high.y() - origin.y())) + 2;
  if (static_cast<double>(width) * height > 64e6)
    throw std::invalid_argument("segmentChanges: the frames span more than 64 million pixels");
  std::vector<double> keyArea(mesh.keyCount());
  for (int k = 0; k < mesh.keyCount(); ++k) keyArea[k] = meshArea(mesh, mesh.keyPositions(k));

  const auto& marks = timeline.marks();
  std::vector<char> previous = silhouetteMask(mesh, frames.front().x, origin, width, height);
  SegmentChanges* current = nullptr;
  const auto close = [&] {
    if (!current) return;
    current->medianPixels = median(current->pixelSteps);
    current->medianRms = median(current->rmsSteps);
    const double typical = median(current->weightSteps);
    const double largest = current->weightSteps.empty() ? 0 : *std::max_element(current->weightSteps.begin(), current->weightSteps.end());
    current->timingPop = typical > 0 ? largest / typical : 1;
  };
  for (size_t f = 1; f < frames.size(); ++f) {
    const AnimationFrame& a = frames[f - 1];
    const AnimationFrame& b = frames[f];
    std::vector<char> mask = silhouetteMask(mesh, b.x, origin, width, height);
    const int segment = timeline.locate(timeline.frameTime(static_cast<int>(f - 1))).segment;
    const bool moving = segment >= 0 && segment + 1 < static_cast<int>(marks.size()) &&
                        (marks[segment].weights - marks[segment + 1].weights).cwiseAbs().maxCoeff() > 1e-12;
    if (moving) {
      if (!current || current->segment != segment) {
        close();
        out.push_back({});
        current = &out.back();
        current->segment = segment;
        current->firstFrame = static_cast<int>(f - 1);
        double interpolated = 0;
        for (Eigen::Index k = 0; k < a.weights.size(); ++k) interpolated += a.weights[k] * keyArea[k];
        current->minAreaRatio = meshArea(mesh, a.x) / interpolated;
        current->minAreaFrame = static_cast<int>(f - 1);
      }
      long changed = 0, area = 0;
      for (size_t i = 0; i < mask.size(); ++i) {
        changed += mask[i] != previous[i];
        area += previous[i];
      }
      const double move = std::sqrt((b.x - a.x).rowwise().squaredNorm().mean());
      current->pixelSteps.push_back(static_cast<double>(changed));
      current->rmsSteps.push_back(move);
      current->weightSteps.push_back((b.weights - a.weights).lpNorm<1>());
      ++current->steps;
      if (changed > current->maxPixels) {
        current->maxPixels = static_cast<double>(changed);
        current->maxPixelsFrame = static_cast<int>(f);
        current->maxPixelsShare = area > 0 ? static_cast<double>(changed) / area : 0;
      }
      if (move > current->maxRms) {
        current->maxRms = move;
        current->maxRmsFrame = static_cast<int>(f);
      }
      double interpolated = 0;
      for (Eigen::Index k = 0; k < b.weights.size(); ++k) interpolated += b.weights[k] * keyArea[k];
      const double ratio = meshArea(mesh, b.x) / interpolated;
      if (ratio < current->minAreaRatio) {
        current->minAreaRatio = ratio;
        current->minAreaFrame = static_cast<int>(f);
      }
      const int heldBefore = heldCount(a), heldAfter = heldCount(b);
      if (heldAfter < heldBefore) current->releases.push_back(static_cast<int>(f));
      if (heldAfter > heldBefore) current->glues.push_back(static_cast<int>(f));
    }
    previous = std::move(mask);
  }
  close();
  return out;
}

}  // namespace ib
