#include "output/cut_ink.h"

#include "multimesh/cut_chains.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace ib::render {

namespace {

// Bilinear straight-alpha sample (colour weighted by alpha), out of the image transparent.
std::array<double, 4> sample(const RgbaImage& image, double x, double y) {
  std::array<double, 4> sum{0, 0, 0, 0};
  const int x0 = static_cast<int>(std::floor(x - 0.5)), y0 = static_cast<int>(std::floor(y - 0.5));
  const double fx = x - 0.5 - x0, fy = y - 0.5 - y0;
  double alpha = 0;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const int px = x0 + dx, py = y0 + dy;
      if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
      const double w = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy);
      const uint8_t* p = image.at(px, py);
      const double a = w * p[3] / 255.0;
      for (int c = 0; c < 3; ++c) sum[c] += a * p[c] / 255.0;
      alpha += a;
    }
  if (alpha > 0)
    for (int c = 0; c < 3; ++c) sum[c] /= alpha;
  sum[3] = alpha;
  return sum;
}

double luminance(const std::array<double, 4>& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

}  // namespace

OutlineInk outlineInk(const RgbaImage& drawing, const Eigen::Vector2d& at, const Eigen::Vector2d& inward, double contrast) {
  OutlineInk ink;
  if (drawing.width <= 0 || inward.norm() <= 0) return ink;
  const Eigen::Vector2d d = inward.normalized();
  constexpr double kStep = 0.5, kFrom = -4, kTo = 24;
  std::vector<std::array<double, 4>> samples;
  std::vector<double> depth;
  for (double t = kFrom; t <= kTo + 1e-9; t += kStep) {
    const Eigen::Vector2d p = at + t * d;
    samples.push_back(sample(drawing, p.x(), p.y()));
    depth.push_back(t);
  }
  size_t first = 0;
  while (first < samples.size() && samples[first][3] < 0.5) ++first;
  if (first == samples.size()) return ink;
  std::vector<double> fill;
  for (size_t i = first; i < samples.size(); ++i)
    if (depth[i] - depth[first] >= 8 && samples[i][3] >= 0.5) fill.push_back(luminance(samples[i]));
  if (fill.size() < 4) return ink;
  std::nth_element(fill.begin(), fill.begin() + fill.size() / 2, fill.end());
  const double fillLuminance = fill[fill.size() / 2];
  size_t end = first;
  double darkest = 1;
  while (end < samples.size() && samples[end][3] >= 0.5 && luminance(samples[end]) <= fillLuminance - contrast) {
    darkest = std::min(darkest, luminance(samples[end]));
    ++end;
  }
  const double width = (end - first) * kStep;
  if (width < 1 || end >= samples.size() || depth.back() - depth[end - 1] < 2) return ink;
  // The colour of the line's core: its samples within a quarter of the way from the darkest to the
  // fill (its edges blend into the fill and the paper).
  std::array<double, 4> sum{0, 0, 0, 0};
  int core = 0;
  for (size_t i = first; i < end; ++i)
    if (luminance(samples[i]) <= darkest + 0.25 * (fillLuminance - darkest)) {
      for (int c = 0; c < 4; ++c) sum[c] += samples[i][c];
      ++core;
    }
  ink.found = true;
  ink.width = width;
  for (int c = 0; c < 4; ++c) ink.colour[c] = static_cast<float>(sum[c] / core);
  return ink;
}

Eigen::Vector2d inwardNormal(const RgbaImage& drawing, const Eigen::Vector2d& at, double radius) {
  Eigen::Vector2d sum(0, 0);
  const auto alpha = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= drawing.width || y >= drawing.height) return 0.0;
    return drawing.at(x, y)[3] / 255.0;
  };
  const int r = static_cast<int>(std::ceil(radius));
  for (int y = static_cast<int>(at.y()) - r; y <= static_cast<int>(at.y()) + r; ++y)
    for (int x = static_cast<int>(at.x()) - r; x <= static_cast<int>(at.x()) + r; ++x) {
      if (std::hypot(x + 0.5 - at.x(), y + 0.5 - at.y()) > radius) continue;
      sum += Eigen::Vector2d(alpha(x + 1, y) - alpha(x - 1, y), alpha(x, y + 1) - alpha(x, y - 1));
    }
  return sum.norm() > 1e-9 ? Eigen::Vector2d(sum.normalized()) : Eigen::Vector2d(0, 0);
}

CutInks cutInksOf(const Multimesh& mesh, const std::vector<RgbaImage>& drawings) {
  CutInks out;
  const int n = mesh.vertexCount(), m = mesh.keyCount();
  // Distinct pairs, the keys that close each, and their cuts.
  const CutChains chains = cutChains(mesh);
  std::vector<std::array<int, 4>> pairs;
  for (const CohesivePair& p : chains.pairs) pairs.push_back({p.a, p.b, p.c, p.d});
  const std::vector<std::vector<char>>& closedIn = chains.closedIn;
  const std::vector<int>& cutOfPair = chains.chainOf;
  for (int c = 0; c < chains.chains; ++c) {
    const int first = static_cast<int>(std::find(cutOfPair.begin(), cutOfPair.end(), c) - cutOfPair.begin());
    out.cuts.push_back({OutlineInk{}, closedIn[first]});
  }
  // The chains' ends: pair vertices used by one pair only (a chain's middle vertices are shared
  // by two), on the mesh boundary in a key that closes the cut.
  std::vector<int> uses(static_cast<size_t>(n), 0);
  for (const auto& pair : pairs)
    for (int v : std::set<int>(pair.begin(), pair.end())) ++uses[v];
  std::vector<char> boundary(static_cast<size_t>(n), 0);
  for (const Edge& e : mesh.boundaryEdges()) boundary[e[0]] = boundary[e[1]] = 1;
  std::vector<std::vector<OutlineInk>> read(out.cuts.size());
  for (size_t p = 0; p < pairs.size(); ++p)
    for (int v : std::set<int>(pairs[p].begin(), pairs[p].end())) {
      if (uses[v] != 1 || !boundary[v]) continue;
      for (int k = 0; k < m; ++k) {
        if (!closedIn[p][k] || k >= static_cast<int>(drawings.size())) continue;
        const Eigen::Vector2d at = mesh.keyPositions(k).row(v).transpose();
        const Eigen::Vector2d inward = inwardNormal(drawings[k], at);
        if (inward.norm() < 0.5) continue;
        const OutlineInk ink = outlineInk(drawings[k], at, inward);
        if (ink.found) read[cutOfPair[p]].push_back(ink);
      }
    }
  for (size_t c = 0; c < out.cuts.size(); ++c) {
    std::vector<OutlineInk>& found = read[c];
    if (found.empty()) continue;
    // The narrowest read, with its colour: a march that crosses the line obliquely, where the
    // outline curves (a narrow neck), only reads it wider.
    out.cuts[c].ink = *std::min_element(found.begin(), found.end(),
                                        [](const OutlineInk& a, const OutlineInk& b) { return a.width < b.width; });
  }
  // Sides, their triangles, and the vertices near them.
  std::map<Edge, int> apexOf;  // edge {min, max} -> the third vertex of a triangle on it
  for (const Triangle& t : mesh.triangles())
    for (int c = 0; c < 3; ++c)
      apexOf.emplace(Edge{std::min(t[c], t[(c + 1) % 3]), std::max(t[c], t[(c + 1) % 3])}, t[(c + 2) % 3]);
  out.near.assign(static_cast<size_t>(n), {});
  std::vector<std::set<int>> sidesAt(static_cast<size_t>(n));
  for (size_t p = 0; p < pairs.size(); ++p) {
    const int cut = cutOfPair[p];
    if (!out.cuts[cut].ink.found) continue;
    const auto closing = std::find(out.cuts[cut].closedIn.begin(), out.cuts[cut].closedIn.end(), 1);
    const int rest = static_cast<int>(closing - out.cuts[cut].closedIn.begin());
    for (const Edge& e : {Edge{pairs[p][0], pairs[p][1]}, Edge{pairs[p][2], pairs[p][3]}}) {
      const auto apex = apexOf.find(Edge{std::min(e[0], e[1]), std::max(e[0], e[1])});
      if (e[0] == e[1] || apex == apexOf.end()) continue;
      const int side = static_cast<int>(out.sides.size());
      out.sides.push_back(e);
      out.sideCut.push_back(cut);
      out.sideApex.push_back(apex->second);
      out.sideRestNormal.push_back(sideNormal(out, side, mesh.keyPositions(rest)));
      sidesAt[e[0]].insert(side);
      sidesAt[e[1]].insert(side);
    }
  }
  for (const Triangle& t : mesh.triangles()) {
    std::set<int> nearby;
    for (int v : t) nearby.insert(sidesAt[v].begin(), sidesAt[v].end());
    for (int v : t)
      for (int side : nearby)
        if (std::find(out.near[v].begin(), out.near[v].end(), side) == out.near[v].end()) out.near[v].push_back(side);
  }
  return out;
}

Eigen::Vector2d sideNormal(const CutInks& inks, int side, const Eigen::MatrixX2d& x) {
  const Edge& e = inks.sides[side];
  const Eigen::Vector2d a = x.row(e[0]).transpose(), along = x.row(e[1]).transpose() - a;
  Eigen::Vector2d normal(-along.y(), along.x());
  if (normal.dot(x.row(inks.sideApex[side]).transpose() - a) < 0) normal = -normal;
  return normal.norm() > 0 ? Eigen::Vector2d(normal.normalized()) : Eigen::Vector2d(0, 0);
}

std::vector<double> openWeights(const CutInks& inks, const Eigen::VectorXd& weights) {
  std::vector<double> open(inks.cuts.size(), 0.0);
  for (size_t c = 0; c < inks.cuts.size(); ++c)
    for (Eigen::Index k = 0; k < weights.size(); ++k)
      if (k >= static_cast<Eigen::Index>(inks.cuts[c].closedIn.size()) || !inks.cuts[c].closedIn[k]) open[c] += weights(k);
  return open;
}

InkFrame inkFrame(const CutInks& inks, const Eigen::MatrixX2d& x, const std::vector<float>& closure,
                  const Eigen::VectorXd& weights, double pixelsPerUnit) {
  const size_t n = static_cast<size_t>(x.rows());
  InkFrame out;
  out.distance.assign(n, 1e6f);
  out.alpha.assign(n, 0.0f);
  out.width.assign(n, 0.0f);
  out.colour.assign(n, {0, 0, 0});
  const std::vector<double> open = openWeights(inks, weights);
  for (size_t v = 0; v < n && v < inks.near.size(); ++v) {
    double best = INFINITY;
    int side = -1;
    const Eigen::Vector2d p = x.row(static_cast<Eigen::Index>(v)).transpose();
    for (int s : inks.near[v]) {
      const Eigen::Vector2d a = x.row(inks.sides[s][0]).transpose(), b = x.row(inks.sides[s][1]).transpose();
      const Eigen::Vector2d d = b - a;
      const double t = std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
      const double distance = (a + t * d - p).norm();
      if (distance < best) best = distance, side = s;
    }
    if (side < 0) continue;
    const CutInks::Cut& cut = inks.cuts[inks.sideCut[side]];
    const float shut = std::max(closure[inks.sides[side][0]], closure[inks.sides[side][1]]);
    out.distance[v] = static_cast<float>(best * pixelsPerUnit);
    out.alpha[v] = inkAlpha(shut, open[inks.sideCut[side]]);
    out.width[v] = static_cast<float>(cut.ink.width * pixelsPerUnit);
    out.colour[v] = {cut.ink.colour[0], cut.ink.colour[1], cut.ink.colour[2]};
  }
  return out;
}

}  // namespace ib::render
