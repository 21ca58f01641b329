#include "meshing/stiffness_paint.h"

#include "core/plane_geometry.h"
#include "core/png_image.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ib {

namespace {

// Log kappa the image asks for at pixel p, blended towards logBase by the pixel's transparency.
double paintedLogKappa(const RgbaImage& image, const Eigen::Vector2d& p, double logSoft, double logStiff,
                       double logBase) {
  const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return logBase;
  const uint8_t* rgba = image.at(x, y);
  const double grey = (0.2126 * rgba[0] + 0.7152 * rgba[1] + 0.0722 * rgba[2]) / 255.0;
  const double opacity = image.hasAlpha ? rgba[3] / 255.0 : 1.0;
  return (1 - opacity) * logBase + opacity * (logSoft + grey * (logStiff - logSoft));
}

// The four sample points of triangle t in key k: centroid, and halfway from it to each corner.
std::array<Eigen::Vector2d, 4> samplePoints(const Eigen::MatrixX2d& X, const Triangle& t) {
  const Eigen::Vector2d a = X.row(t[0]), b = X.row(t[1]), c = X.row(t[2]);
  const Eigen::Vector2d centroid = (a + b + c) / 3;
  return {centroid, 0.5 * (centroid + a), 0.5 * (centroid + b), 0.5 * (centroid + c)};
}

// Distance from p to the open polyline (to its point when it has one), px.
double distanceToPolyline(const Polyline& points, const Eigen::Vector2d& p) {
  double nearest = (points.front() - p).norm();
  for (size_t i = 1; i < points.size(); ++i) {
    const double u = closestParameter(points[i - 1], points[i], p);
    nearest = std::min(nearest, (points[i - 1] + u * (points[i] - points[i - 1]) - p).norm());
  }
  return nearest;
}

}  // namespace

void paintStiffness(Multimesh& mesh, const StiffnessPaint& paint, double base) {
  const std::vector<Triangle> triangles = mesh.triangles();
  const int count = static_cast<int>(triangles.size());
  for (int t = 0; t < count; ++t) mesh.setStiffness(t, base);
  if (!paint.image.empty()) {
    const RgbaImage image = readPng(paint.image);
    const Eigen::MatrixX2d X = mesh.keyPositions(paint.imageKey);
    const double logSoft = std::log(paint.soft), logStiff = std::log(paint.stiff), logBase = std::log(base);
    for (int t = 0; t < count; ++t) {
      double sum = 0;
      for (const Eigen::Vector2d& p : samplePoints(X, triangles[t]))
        sum += paintedLogKappa(image, p, logSoft, logStiff, logBase);
      mesh.setStiffness(t, std::exp(sum / 4));
    }
  }
  for (const StiffnessRegion& region : paint.regions) {
    const Eigen::MatrixX2d X = mesh.keyPositions(region.key);
    for (int t = 0; t < count; ++t) {
      const Eigen::Vector2d centroid = samplePoints(X, triangles[t])[0];
      if (rayCrossings(region.polygon, centroid) % 2 == 1) mesh.setStiffness(t, region.kappa);
    }
  }
  for (const StiffnessStroke& stroke : paint.strokes) {
    const Eigen::MatrixX2d X = mesh.keyPositions(stroke.key);
    for (int t = 0; t < count; ++t)
      if (distanceToPolyline(stroke.points, samplePoints(X, triangles[t])[0]) <= stroke.radius)
        mesh.setStiffness(t, stroke.kappa);
  }
}

}  // namespace ib
