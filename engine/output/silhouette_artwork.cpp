#include "output/silhouette_artwork.h"

#include "core/plane_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace ib::render {
namespace {

constexpr uint8_t kSolid = 128;  // alpha from which a texel's own colour is trusted

struct Grid {
  int w = 0, h = 0;
  size_t at(int x, int y) const { return static_cast<size_t>(y) * w + x; }
};

// Texels whose centre lies in some triangle (either orientation), as 0/1. Each triangle's three
// edge functions are affine in the texel centre: evaluated as a x + b y + c, signed by the
// triangle's orientation, so a centre on an edge counts.
std::vector<char> coveredTexels(const Grid& g, const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& x) {
  std::vector<char> inside(static_cast<size_t>(g.w) * g.h, 0);
  for (const Triangle& t : triangles) {
    const Eigen::Vector2d p[3] = {x.row(t[0]).transpose(), x.row(t[1]).transpose(), x.row(t[2]).transpose()};
    const double area = orient(p[0], p[1], p[2]);
    if (!(std::abs(area) > 0)) continue;
    const double sign = area > 0 ? 1 : -1;
    double a[3], b[3], c[3];  // edge e (p[e] to p[e + 1]): orient(p[e], p[e + 1], q) = a q.x + b q.y + c
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector2d& u = p[e];
      const Eigen::Vector2d& v = p[(e + 1) % 3];
      a[e] = sign * (u.y() - v.y());
      b[e] = sign * (v.x() - u.x());
      c[e] = sign * (u.x() * v.y() - u.y() * v.x());
    }
    const Eigen::Vector2d lo = p[0].cwiseMin(p[1]).cwiseMin(p[2]), hi = p[0].cwiseMax(p[1]).cwiseMax(p[2]);
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x() - 0.5))), x1 = std::min(g.w - 1, static_cast<int>(std::ceil(hi.x() - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::floor(lo.y() - 0.5))), y1 = std::min(g.h - 1, static_cast<int>(std::ceil(hi.y() - 0.5)));
    for (int py = y0; py <= y1; ++py) {
      const double qy = py + 0.5;
      for (int px = x0; px <= x1; ++px) {
        const double qx = px + 0.5;
        if (a[0] * qx + b[0] * qy + c[0] >= 0 && a[1] * qx + b[1] * qy + c[1] >= 0 && a[2] * qx + b[2] * qy + c[2] >= 0)
          inside[g.at(px, py)] = 1;
      }
    }
  }
  return inside;
}

// Texels whose centre lies within `band` of some boundary edge, as 0/1.
std::vector<char> bandTexels(const Grid& g, const std::vector<Edge>& boundary, const Eigen::MatrixX2d& x, double band) {
  std::vector<char> near(static_cast<size_t>(g.w) * g.h, 0);
  for (const Edge& e : boundary) {
    const Eigen::Vector2d a = x.row(e[0]).transpose(), b = x.row(e[1]).transpose();
    const Eigen::Vector2d lo = a.cwiseMin(b).array() - band, hi = a.cwiseMax(b).array() + band;
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x() - 0.5))), x1 = std::min(g.w - 1, static_cast<int>(std::ceil(hi.x() - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::floor(lo.y() - 0.5))), y1 = std::min(g.h - 1, static_cast<int>(std::ceil(hi.y() - 0.5)));
    for (int py = y0; py <= y1; ++py)
      for (int px = x0; px <= x1; ++px) {
        const Eigen::Vector2d p(px + 0.5, py + 0.5);
        if ((a + closestParameter(a, b, p) * (b - a) - p).norm() <= band) near[g.at(px, py)] = 1;
      }
  }
  return near;
}

// Spreads `value` from the texels where `known` into the band texels, one 8-connected ring per
// pass for at most `passes` rings; `merge(into, from)` combines a neighbour's value into a texel's.
template <class Value, class Merge>
void spreadIntoBand(const Grid& g, const std::vector<char>& band, std::vector<char>& known, std::vector<Value>& value,
                    int passes, Merge merge) {
  // The first frontier: the known texels beside a band texel still to reach (the others reach none).
  std::vector<size_t> frontier, next;
  std::vector<char> seeded(known.size(), 0);
  for (int y = 0; y < g.h; ++y)
    for (int x = 0; x < g.w; ++x) {
      if (!band[g.at(x, y)] || known[g.at(x, y)]) continue;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= g.w || ny >= g.h) continue;
          const size_t j = g.at(nx, ny);
          if (known[j] && !seeded[j]) seeded[j] = 1, frontier.push_back(j);
        }
    }
  for (int pass = 0; pass < passes && !frontier.empty(); ++pass) {
    next.clear();
    for (size_t i : frontier) {
      const int x = static_cast<int>(i % g.w), y = static_cast<int>(i / g.w);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= g.w || ny >= g.h) continue;
          const size_t j = g.at(nx, ny);
          if (!band[j] || known[j] == 1) continue;
          if (known[j] == 0) next.push_back(j);
          known[j] = 2;  // reached in this pass: takes every neighbour of the pass before
          merge(value[j], value[i]);
        }
    }
    for (size_t j : next) known[j] = 1;
    frontier.swap(next);
  }
}

}  // namespace

RgbaImage silhouetteArtwork(const RgbaImage& drawing, const std::vector<Triangle>& triangles, const std::vector<Edge>& boundary,
                            const Eigen::MatrixX2d& positions, const SilhouetteOptions& options) {
  if (!(options.band > 0) || drawing.width <= 0 || drawing.height <= 0) return drawing;
  const Grid g{drawing.width, drawing.height};
  const std::vector<char> inside = coveredTexels(g, triangles, positions);
  const std::vector<char> band = bandTexels(g, boundary, positions, options.band);
  const size_t count = static_cast<size_t>(g.w) * g.h;
  const int passes = static_cast<int>(std::ceil(2 * options.band)) + 2;

  // The interior's opacity, spread over the band from the covered texels beyond it.
  std::vector<char> known(count, 0);
  std::vector<uint8_t> opacity(count, 0);
  for (size_t i = 0; i < count; ++i)
    if (inside[i] && !band[i]) {
      known[i] = 1;
      opacity[i] = drawing.pixels[4 * i + 3];
    }
  spreadIntoBand(g, band, known, opacity, passes, [](uint8_t& into, uint8_t from) { into = std::max(into, from); });
  // A band with no interior beside it (a limb thinner than the band) is opaque.
  for (size_t i = 0; i < count; ++i)
    if (band[i] && !known[i]) opacity[i] = 255;

  // The colour of the nearest solid texel, for band texels too transparent to trust their own.
  std::vector<char> solid(count, 0);
  // Summed RGB of the neighbours it came from and their count (at most 8 x 255: 16 bits do).
  std::vector<std::array<uint16_t, 4>> colour(count, {0, 0, 0, 0});
  for (size_t i = 0; i < count; ++i)
    if (drawing.pixels[4 * i + 3] >= kSolid) {
      solid[i] = 1;
      colour[i] = {drawing.pixels[4 * i], drawing.pixels[4 * i + 1], drawing.pixels[4 * i + 2], uint16_t{1}};
    }
  spreadIntoBand(g, band, solid, colour, passes, [](std::array<uint16_t, 4>& into, const std::array<uint16_t, 4>& from) {
    if (from[3] == 0) return;
    for (int c = 0; c < 3; ++c) into[c] = static_cast<uint16_t>(into[c] + from[c] / from[3]);
    ++into[3];
  });

  RgbaImage out = drawing;
  out.hasAlpha = true;
  for (size_t i = 0; i < count; ++i) {
    if (!band[i]) continue;
    uint8_t* p = &out.pixels[4 * i];
    if (p[3] < kSolid && colour[i][3] > 0)
      for (int c = 0; c < 3; ++c) p[c] = static_cast<uint8_t>((colour[i][c] + colour[i][3] / 2) / colour[i][3]);
    p[3] = std::max(p[3], opacity[i]);
  }
  return out;
}

}  // namespace ib::render
