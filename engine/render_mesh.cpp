#include "render_mesh.h"

#include "error.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace ib::render {

RenderMesh renderMeshOf(const Multimesh& mesh, std::vector<RgbaImage> artwork, std::vector<int> features) {
  if (static_cast<int>(artwork.size()) != mesh.keyCount())
    throw InputError("render: " + std::to_string(artwork.size()) + " drawings for " + std::to_string(mesh.keyCount()) +
                     " keys");
  RenderMesh out;
  out.vertexCount = mesh.vertexCount();
  out.triangles = mesh.triangles();
  for (int k = 0; k < mesh.keyCount(); ++k) {
    const RgbaImage& image = artwork[k];
    if (image.width <= 0 || image.height <= 0) throw InputError("render: the drawing of key " + std::to_string(k) + " is empty");
    Eigen::MatrixX2f uv = mesh.keyPositions(k).cast<float>();
    uv.col(0) /= static_cast<float>(image.width);
    uv.col(1) /= static_cast<float>(image.height);
    out.keyUV.push_back(std::move(uv));
    std::vector<Edge> cohesive;
    for (const CohesivePair& p : mesh.cohesivePairs(k)) {
      cohesive.push_back({p.a, p.b});
      cohesive.push_back({p.c, p.d});
    }
    out.cohesiveEdges.push_back(std::move(cohesive));
  }
  std::set<Edge> edges;
  for (const Triangle& t : out.triangles)
    for (int e = 0; e < 3; ++e) edges.insert({std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])});
  out.edges.assign(edges.begin(), edges.end());
  for (int f : features)
    if (f < 0 || f >= out.vertexCount) throw InputError("render: feature vertex " + std::to_string(f) + " is not in the mesh");
  out.features = std::move(features);
  out.artwork = std::move(artwork);
  return out;
}

ViewBox fitView(const ViewBox& bounds, int width, int height, double margin) {
  const double w = std::max(bounds.x1 - bounds.x0, 1e-9), h = std::max(bounds.y1 - bounds.y0, 1e-9);
  const double grow = margin * std::max(w, h);
  double halfW = 0.5 * w + grow, halfH = 0.5 * h + grow;
  const double aspect = static_cast<double>(width) / height;
  if (halfW / halfH < aspect) halfW = halfH * aspect;
  else halfH = halfW / aspect;
  const double cx = 0.5 * (bounds.x0 + bounds.x1), cy = 0.5 * (bounds.y0 + bounds.y1);
  return {cx - halfW, cy - halfH, cx + halfW, cy + halfH};
}

ViewBox boundsOf(const std::vector<Eigen::MatrixX2d>& points) {
  ViewBox box{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const Eigen::MatrixX2d& p : points) {
    if (p.rows() == 0) continue;
    box.x0 = std::min(box.x0, p.col(0).minCoeff());
    box.y0 = std::min(box.y0, p.col(1).minCoeff());
    box.x1 = std::max(box.x1, p.col(0).maxCoeff());
    box.y1 = std::max(box.y1, p.col(1).maxCoeff());
  }
  if (!(box.x0 <= box.x1)) throw InputError("render: nothing to frame (no positions)");
  return box;
}

}  // namespace ib::render
