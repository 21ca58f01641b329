#include "output/render_mesh.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace ib::render {

namespace {

CutSides cutSidesOf(const Multimesh& mesh) {
  std::map<std::array<int, 4>, int> pairs;  // pair -> its index in CutSides::pairs
  std::vector<std::array<int, 4>> terms;
  std::set<Edge> partners;
  for (int k = 0; k < mesh.keyCount(); ++k)
    for (const CohesivePair& p : mesh.cohesivePairs(k)) {
      terms.push_back({p.a, p.b, p.c, p.d});
      pairs.insert({terms.back(), 0});
      for (const Edge& e : {Edge{p.a, p.c}, Edge{p.b, p.d}})
        if (e[0] != e[1]) partners.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
    }
  CutSides out;
  std::vector<char> onCut(mesh.vertexCount(), 0);
  for (auto& [p, index] : pairs) {
    index = static_cast<int>(out.pairs.size());
    out.pairs.push_back({p[0], p[1], p[2], p[3]});
    for (int v : p) onCut[v] = 1;
  }
  for (const std::array<int, 4>& t : terms) out.pairOfTerm.push_back(pairs.at(t));
  out.partners.assign(partners.begin(), partners.end());
  const auto partnerIndex = [&](int u, int v) {
    if (u == v) return -1;
    const Edge e{std::min(u, v), std::max(u, v)};
    return static_cast<int>(std::lower_bound(out.partners.begin(), out.partners.end(), e) - out.partners.begin());
  };
  for (const CohesivePair& p : out.pairs) out.pairPartners.push_back({partnerIndex(p.a, p.c), partnerIndex(p.b, p.d)});
  std::set<Edge> ring;
  for (const Triangle& t : mesh.triangles())
    for (int e = 0; e < 3; ++e)
      for (const auto& [v, w] : {std::pair{t[e], t[(e + 1) % 3]}, std::pair{t[(e + 1) % 3], t[e]}})
        if (!onCut[v] && onCut[w]) ring.insert({v, w});
  out.ring.assign(ring.begin(), ring.end());
  return out;
}

// 1 at gaps (target pixels) up to `glued`, 0 from `open` on, linear in between.
double closureAt(double gap, const CutWeldOptions& options) {
  return std::clamp((options.open - gap) / (options.open - options.glued), 0.0, 1.0);
}

}  // namespace

RenderMesh renderMeshOf(const Multimesh& mesh, std::vector<RgbaImage> artwork, std::vector<int> features,
                        const SilhouetteOptions& silhouette) {
  if (static_cast<int>(artwork.size()) != mesh.keyCount())
    throw std::invalid_argument("render: " + std::to_string(artwork.size()) + " drawings for " + std::to_string(mesh.keyCount()) +
                     " keys");
  RenderMesh out;
  out.vertexCount = mesh.vertexCount();
  out.triangles = mesh.triangles();
  for (int k = 0; k < mesh.keyCount(); ++k) {
    const RgbaImage& image = artwork[k];
    if (image.width <= 0 || image.height <= 0) throw std::invalid_argument("render: the drawing of key " + std::to_string(k) + " is empty");
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
  out.cutSides = cutSidesOf(mesh);
  std::set<Edge> edges;
  for (const Triangle& t : out.triangles)
    for (int e = 0; e < 3; ++e) edges.insert({std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])});
  out.edges.assign(edges.begin(), edges.end());
  for (int f : features)
    if (f < 0 || f >= out.vertexCount) throw std::invalid_argument("render: feature vertex " + std::to_string(f) + " is not in the mesh");
  out.features = std::move(features);
  out.inks = cutInksOf(mesh, artwork);
  out.drawings = artwork;
  out.rim = keyRimOf(mesh);
  for (int k = 0; k < mesh.keyCount(); ++k) {
    Eigen::MatrixX2f uv = rimPoints(out.rim, mesh.keyPositions(k)).cast<float>();
    uv.col(0) /= static_cast<float>(artwork[k].width);
    uv.col(1) /= static_cast<float>(artwork[k].height);
    out.rimUV.push_back(std::move(uv));
  }
  // Each key's on its own, in parallel; an exception (out of memory) is rethrown here.
  std::exception_ptr failed;
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < mesh.keyCount(); ++k) {
    try {
      artwork[k] = silhouetteArtwork(artwork[k], out.triangles, mesh.boundaryEdges(), mesh.keyPositions(k), silhouette);
    } catch (...) {
#pragma omp critical(render_mesh_failed)
      if (!failed) failed = std::current_exception();
    }
  }
  if (failed) std::rethrow_exception(failed);
  out.artwork = std::move(artwork);
  return out;
}

std::vector<RgbaImage> textureLayers(const RenderMesh& mesh) {
  std::vector<RgbaImage> layers = mesh.artwork;
  layers.insert(layers.end(), mesh.drawings.begin(), mesh.drawings.end());
  return layers;
}

CutWeld weldCuts(const Eigen::MatrixX2d& x, const CutSides& cutSides, double pixelsPerUnit, const CutWeldOptions& options,
                   const std::vector<char>* heldPairs) {
  if (!(options.glued >= 0 && options.open > options.glued))
    throw std::invalid_argument("render: cut welding needs 0 <= glued < open pixels");
  if (!(pixelsPerUnit > 0 && std::isfinite(pixelsPerUnit))) throw std::invalid_argument("render: cut welding needs a positive scale");
  if (heldPairs && heldPairs->size() != cutSides.pairOfTerm.size())
    throw std::invalid_argument("render: " + std::to_string(heldPairs->size()) + " held-pair flags for " +
                     std::to_string(cutSides.pairOfTerm.size()) + " cohesive pairs");
  if (heldPairs && cutSides.pairPartners.size() != cutSides.pairs.size())
    throw std::invalid_argument("render: held-pair flags need cutSides with pairPartners (renderMeshOf's)");
  const Eigen::Index n = x.rows();
  CutWeld out{x, std::vector<float>(n, 0.0f)};
  if (cutSides.pairs.empty()) return out;
  std::vector<char> held(cutSides.pairs.size(), 0), heldPartner(cutSides.partners.size(), 0);
  for (size_t t = 0; heldPairs && t < heldPairs->size(); ++t)
    if ((*heldPairs)[t]) held[cutSides.pairOfTerm[t]] = 1;
  for (size_t j = 0; j < cutSides.pairs.size(); ++j) {
    const CohesivePair& p = cutSides.pairs[j];
    const double gap = pixelsPerUnit * std::max((x.row(p.a) - x.row(p.c)).norm(), (x.row(p.b) - x.row(p.d)).norm());
    const float c = held[j] ? 1.0f : static_cast<float>(closureAt(gap, options));
    for (int v : {p.a, p.b, p.c, p.d}) out.closure[v] = std::max(out.closure[v], c);
    if (held[j])
      for (int e : cutSides.pairPartners[j])
        if (e >= 0) heldPartner[e] = 1;
  }
  for (const Edge& e : cutSides.ring) out.closure[e[0]] = std::max(out.closure[e[0]], out.closure[e[1]]);
  Eigen::MatrixX2d pull = Eigen::MatrixX2d::Zero(n, 2);  // sum_v c_uv (v - u) per vertex u
  Eigen::VectorXd pulls = Eigen::VectorXd::Zero(n);       // sum_v c_uv
  for (size_t k = 0; k < cutSides.partners.size(); ++k) {
    const Edge& e = cutSides.partners[k];
    const Eigen::RowVector2d d = x.row(e[1]) - x.row(e[0]);
    const double c = heldPartner[k] ? 1.0 : closureAt(pixelsPerUnit * d.norm(), options);
    pull.row(e[0]) += c * d;
    pull.row(e[1]) -= c * d;
    pulls[e[0]] += c;
    pulls[e[1]] += c;
  }
  for (Eigen::Index v = 0; v < n; ++v)
    if (pulls[v] > 0) out.positions.row(v) += pull.row(v) / (1 + pulls[v]);
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
  if (!(box.x0 <= box.x1)) throw std::invalid_argument("render: nothing to frame (no positions)");
  return box;
}

}  // namespace ib::render
