#include "export/ink_strips.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace ib::gltf {

namespace {

// The sRGB transfer function undone: glTF vertex colours are linear, the drawings' sRGB.
float linear(float srgb) {
  return srgb <= 0.04045f ? srgb / 12.92f : std::pow((srgb + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

InkStrips inkStripsOf(const render::CutInks& inks, const std::vector<Triangle>& triangles) {
  InkStrips strips;
  // The mesh's boundary edges (in one triangle), by vertex: the cuts' sides and the outline.
  std::map<Edge, int> edgeUses;
  for (const Triangle& t : triangles)
    for (int c = 0; c < 3; ++c) ++edgeUses[Edge{std::min(t[c], t[(c + 1) % 3]), std::max(t[c], t[(c + 1) % 3])}];
  std::set<Edge> sideEdges;
  for (const Edge& e : inks.sides) sideEdges.insert(Edge{std::min(e[0], e[1]), std::max(e[0], e[1])});
  std::map<int, std::vector<int>> outlineNext;  // vertex -> its neighbours along boundary edges that are no side
  for (const auto& [e, uses] : edgeUses)
    if (uses == 1 && !sideEdges.count(e)) outlineNext[e[0]].push_back(e[1]), outlineNext[e[1]].push_back(e[0]);
  // At each (cut, vertex), the sides meeting there split into the cut's two faces: sides of one
  // face have inward normals that agree where the cut is closed, the other face's are opposite.
  // One outer and one inner strip vertex per (cut, vertex, face).
  std::map<std::pair<int, int>, std::vector<int>> sidesAt;
  for (size_t s = 0; s < inks.sides.size(); ++s)
    for (int v : inks.sides[s]) sidesAt[{inks.sideCut[s], v}].push_back(static_cast<int>(s));
  std::map<std::pair<int, int>, std::array<int, 2>> stripVertex;  // (side, end) -> {outer, inner}
  for (const auto& [at, sides] : sidesAt) {
    std::vector<std::vector<int>> faces;
    for (int s : sides) {
      auto face = std::find_if(faces.begin(), faces.end(), [&](const std::vector<int>& f) {
        return inks.sideRestNormal[f.front()].dot(inks.sideRestNormal[s]) > 0;
      });
      if (face == faces.end()) faces.push_back({s});
      else face->push_back(s);
    }
    for (const std::vector<int>& face : faces) {
      const int outer = strips.vertexCount();
      const auto next = outlineNext.find(at.second);
      const std::vector<int> outline = next == outlineNext.end() ? std::vector<int>{} : next->second;
      for (int inner = 0; inner < 2; ++inner) {
        strips.source.push_back(at.second);
        strips.cut.push_back(at.first);
        strips.inward.push_back(inner ? face : std::vector<int>{});
        strips.along.push_back(inner ? outline : std::vector<int>{});
      }
      for (int s : face) stripVertex[{s, inks.sides[s][0] == at.second ? 0 : 1}] = {outer, outer + 1};
    }
  }
  for (size_t s = 0; s < inks.sides.size(); ++s) {
    const std::array<int, 2> a = stripVertex.at({static_cast<int>(s), 0}), b = stripVertex.at({static_cast<int>(s), 1});
    strips.triangles.push_back({a[0], b[0], b[1]});
    strips.triangles.push_back({a[0], b[1], a[1]});
  }
  return strips;
}

Eigen::MatrixX2d inkStripPositions(const InkStrips& strips, const render::CutInks& inks, const Eigen::MatrixX2d& x) {
  Eigen::MatrixX2d out(strips.vertexCount(), 2);
  for (int v = 0; v < strips.vertexCount(); ++v) {
    Eigen::Vector2d p = x.row(strips.source[v]).transpose(), direction(0, 0);
    for (int s : strips.inward[v]) direction += render::sideNormal(inks, s, x);
    const double width = inks.cuts[strips.cut[v]].ink.width;
    if (direction.norm() > 1e-9) {
      direction.normalize();
      Eigen::Vector2d step = width * direction;
      // Slide along the outline neighbour most across the strip to the line's width from the side,
      // unless the outline leaves the side at a grazing angle (the strip's end would run far along it).
      double across = 0.3;
      for (int u : strips.along[v]) {
        const Eigen::Vector2d outline = x.row(u).transpose() - p;
        if (outline.norm() < 1e-12) continue;
        const double c = outline.normalized().dot(direction);
        if (c > across) across = c, step = width / c * outline.normalized();
      }
      p += step;
    }
    out.row(v) = p.transpose();
  }
  return out;
}

std::vector<float> inkStripColours(const InkStrips& strips, const render::CutInks& inks, const std::vector<float>& closure,
                                   const Eigen::VectorXd& weights) {
  const std::vector<double> open = render::openWeights(inks, weights);
  std::vector<float> out;
  out.reserve(4 * static_cast<size_t>(strips.vertexCount()));
  for (int v = 0; v < strips.vertexCount(); ++v) {
    const int c = strips.cut[v];
    const auto& colour = inks.cuts[c].ink.colour;
    const float shut = static_cast<size_t>(strips.source[v]) < closure.size() ? closure[strips.source[v]] : 0.0f;
    out.insert(out.end(), {linear(colour[0]), linear(colour[1]), linear(colour[2]), render::inkAlpha(shut, open[c])});
  }
  return out;
}

}  // namespace ib::gltf
