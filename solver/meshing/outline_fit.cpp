#include "meshing/outline_fit.h"

#include "core/box_grid.h"
#include "core/plane_geometry.h"

#include <cmath>
#include <stdexcept>

namespace ib {
namespace {

constexpr double kStep = 0.25;  // px between samples along either side

using Segments = std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>;

// Nearest-segment distances over a grid of the segments' boxes.
class SegmentSet {
 public:
  explicit SegmentSet(Segments segments) : segments_(std::move(segments)), grid_(boxes(segments_, true), boxes(segments_, false), cell(segments_)) {}

  double distance(const Eigen::Vector2d& p) const {
    double best = INFINITY;
    for (int ring = 0;; ++ring) {
      // Segments in later rings are at least ring * cell away.
      if (best <= (ring - 1) * grid_.cellSize()) break;
      const bool inside = grid_.visitRing(p, ring, [&](int s) {
        const auto& [a, b] = segments_[s];
        best = std::min(best, (a + closestParameter(a, b, p) * (b - a) - p).norm());
      });
      if (!inside) break;
    }
    return best;
  }

  const Segments& segments() const { return segments_; }

 private:
  static Eigen::MatrixX2d boxes(const Segments& s, bool lo) {
    Eigen::MatrixX2d out(static_cast<Eigen::Index>(s.size()), 2);
    for (size_t i = 0; i < s.size(); ++i) {
      const Eigen::Vector2d corner = lo ? Eigen::Vector2d(s[i].first.cwiseMin(s[i].second)) : Eigen::Vector2d(s[i].first.cwiseMax(s[i].second));
      out.row(static_cast<Eigen::Index>(i)) = corner.transpose();
    }
    return out;
  }
  static double cell(const Segments& s) {
    double total = 0;
    for (const auto& [a, b] : s) total += (b - a).norm();
    return std::max(1.0, s.empty() ? 1.0 : 2 * total / static_cast<double>(s.size()));
  }
  Segments segments_;
  BoxGrid grid_;
};

// The farthest sample of `from` from `to`.
void farthest(const SegmentSet& from, const SegmentSet& to, OutlineFit& fit) {
  for (const auto& [a, b] : from.segments()) {
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / kStep)));
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(j) / n);
      const double d = to.distance(p);
      if (d > fit.largest) {
        fit.largest = d;
        fit.where = p;
      }
    }
  }
}

}  // namespace

std::vector<OutlineFit> outlineFits(const Multimesh& mesh, const std::vector<KeyShape>& shapes) {
  if (static_cast<int>(shapes.size()) != mesh.keyCount())
    throw std::invalid_argument("outlineFits: " + std::to_string(shapes.size()) + " shapes for " + std::to_string(mesh.keyCount()) + " keys");
  std::vector<OutlineFit> fits(shapes.size());
  for (int k = 0; k < mesh.keyCount(); ++k) {
    const Eigen::MatrixX2d& x = mesh.keyPositions(k);
    Segments boundary, outline;
    for (const Edge& e : mesh.boundaryEdges()) boundary.emplace_back(x.row(e[0]).transpose(), x.row(e[1]).transpose());
    for (const ShapeLoop& loop : shapes[k].loops)
      for (size_t i = 0; i < loop.points.size(); ++i)
        outline.emplace_back(loop.points[i], loop.points[(i + 1) % loop.points.size()]);
    if (boundary.empty() || outline.empty()) continue;
    const SegmentSet b(std::move(boundary)), o(std::move(outline));
    farthest(o, b, fits[k]);
    farthest(b, o, fits[k]);
  }
  return fits;
}

}  // namespace ib
