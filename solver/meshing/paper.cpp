#include "meshing/paper.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace ib {

namespace {

std::string pointText(const Eigen::Vector2d& p) {
  auto num = [](double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
  };
  return "[" + num(p.x()) + ", " + num(p.y()) + "]";
}

double distance2(const uint8_t* p, const std::array<int, 3>& colour) {
  double d2 = 0;
  for (int c = 0; c < 3; ++c) d2 += double(p[c] - colour[c]) * (p[c] - colour[c]);
  return d2;
}

// Spreads `seeds` through the 4-connected pixels where `open` is set, marking them in `reached`.
void flood(std::deque<size_t>& seeds, const std::vector<uint8_t>& open, int width, int height,
           std::vector<uint8_t>& reached) {
  while (!seeds.empty()) {
    const size_t i = seeds.front();
    seeds.pop_front();
    const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
    const size_t next[4] = {i - 1, i + 1, i - width, i + width};
    const bool inside[4] = {x > 0, x + 1 < width, y > 0, y + 1 < height};
    for (int k = 0; k < 4; ++k)
      if (inside[k] && open[next[k]] && !reached[next[k]]) {
        reached[next[k]] = 1;
        seeds.push_back(next[k]);
      }
  }
}

// 1 where `mask` is set within `radius` px (Chebyshev) of the pixel: a box dilation, separable.
std::vector<uint8_t> dilate(const std::vector<uint8_t>& mask, int width, int height, int radius) {
  std::vector<uint8_t> rows(mask.size()), out(mask.size());
  std::vector<int> sum;
  for (int y = 0; y < height; ++y) {
    sum.assign(width + 1, 0);
    for (int x = 0; x < width; ++x) sum[x + 1] = sum[x] + mask[static_cast<size_t>(y) * width + x];
    for (int x = 0; x < width; ++x)
      rows[static_cast<size_t>(y) * width + x] = sum[std::min(width, x + radius + 1)] > sum[std::max(0, x - radius)];
  }
  for (int x = 0; x < width; ++x) {
    sum.assign(height + 1, 0);
    for (int y = 0; y < height; ++y) sum[y + 1] = sum[y] + rows[static_cast<size_t>(y) * width + x];
    for (int y = 0; y < height; ++y)
      out[static_cast<size_t>(y) * width + x] = sum[std::min(height, y + radius + 1)] > sum[std::max(0, y - radius)];
  }
  return out;
}

using Rgb = Eigen::Vector3d;

Rgb rgbAt(const RgbaImage& image, size_t i) {
  const uint8_t* p = image.pixels.data() + 4 * i;
  return {double(p[0]), double(p[1]), double(p[2])};
}

// GIMP's colour-to-alpha: the least alpha a with p = a ink + (1 - a) paper for some ink colour
// in the RGB cube.
double colourToAlpha(const Rgb& p, const Rgb& paper) {
  double a = 0;
  for (int c = 0; c < 3; ++c) {
    if (p[c] > paper[c] && paper[c] < 255) a = std::max(a, (p[c] - paper[c]) / (255 - paper[c]));
    if (p[c] < paper[c] && paper[c] > 0) a = std::max(a, (paper[c] - p[c]) / paper[c]);
  }
  return std::min(a, 1.0);
}

}  // namespace

bool tracedByColour(const RgbaImage& image, const TracingOptions& options) {
  if (options.background.has_value() || !image.hasAlpha) return true;
  // An alpha channel that is opaque everywhere (an export on paper saved as RGBA) marks no shape:
  // traced by alpha, the whole canvas would be one rectangle.
  for (size_t i = 3; i < image.pixels.size(); i += 4)
    if (image.pixels[i] < options.alphaThreshold) return false;
  return true;
}

PaperMap findPaper(const RgbaImage& image, const TracingOptions& options, const Polyline& holePoints,
                   const std::string& label) {
  PaperMap map;
  map.width = image.width;
  map.height = image.height;
  map.colour = options.background.value_or(std::array<int, 3>{255, 255, 255});
  const int w = image.width, h = image.height;
  const size_t n = static_cast<size_t>(w) * h;
  const double threshold2 = options.colorThreshold * options.colorThreshold;
  std::vector<uint8_t> paperColoured(n), transparent(n);
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = image.pixels.data() + 4 * i;
    transparent[i] = image.hasAlpha && p[3] < options.alphaThreshold;
    paperColoured[i] = transparent[i] || distance2(p, map.colour) <= threshold2;
  }
  if (options.holes == PaperHoles::kEnclosedPaper) {
    map.paper = paperColoured;
    return map;
  }
  map.paper.assign(n, 0);
  std::deque<size_t> seeds;
  auto seed = [&](size_t i) {
    if (paperColoured[i] && !map.paper[i]) map.paper[i] = 1, seeds.push_back(i);
  };
  for (int x = 0; x < w; ++x) seed(x), seed(static_cast<size_t>(h - 1) * w + x);
  for (int y = 0; y < h; ++y) seed(static_cast<size_t>(y) * w), seed(static_cast<size_t>(y) * w + w - 1);
  for (size_t i = 0; i < n; ++i)
    if (transparent[i]) seed(i);
  flood(seeds, paperColoured, w, h, map.paper);
  for (size_t k = 0; k < holePoints.size(); ++k) {
    const Eigen::Vector2d& q = holePoints[k];
    const std::string at = label + ": holes: point " + std::to_string(k + 1) + " " + pointText(q);
    const int x = static_cast<int>(std::floor(q.x())), y = static_cast<int>(std::floor(q.y()));
    if (!(x >= 0 && x < w && y >= 0 && y < h))
      throw InputError(at + " is off the drawing (" + std::to_string(w) + " x " + std::to_string(h) + " px)");
    const size_t i = static_cast<size_t>(y) * w + x;
    const uint8_t* p = image.at(x, y);
    if (!paperColoured[i])
      throw InputError(at + " is on the drawing's ink (RGB " + std::to_string(p[0]) + ", " + std::to_string(p[1]) +
                       ", " + std::to_string(p[2]) + "), not on paper; put it inside the paper-coloured region "
                       "that should be a hole");
    if (map.paper[i])
      throw InputError(at + " is in the paper round the drawing, not in a region the drawing encloses (that "
                       "paper is transparent anyway); remove it or move it into the hole");
  }
  for (const Eigen::Vector2d& q : holePoints) seed(static_cast<size_t>(std::floor(q.y())) * w + std::floor(q.x()));
  flood(seeds, paperColoured, w, h, map.paper);
  return map;
}

RgbaImage paperToAlpha(const RgbaImage& image, const PaperMap& paper) {
  const int w = image.width, h = image.height;
  const size_t n = static_cast<size_t>(w) * h;
  constexpr int kFringe = 2;     // px: pixels of the shape this close to paper may be blended with it
  constexpr int kSearch = 4;     // px: how far to look for the ink colour a fringe pixel blends
  const Rgb colour(paper.colour[0], paper.colour[1], paper.colour[2]);
  std::vector<uint8_t> shape(n);
  for (size_t i = 0; i < n; ++i) shape[i] = !paper.paper[i];
  const std::vector<uint8_t> nearPaper = dilate(paper.paper, w, h, kFringe);
  const std::vector<uint8_t> nearShape = dilate(shape, w, h, 1);
  // Ink: shape pixels that are not paper-coloured (enclosed paper is kept as it is). Solid ink
  // gives the colours that fringe pixels are blends of.
  const double inkDistance = 16;  // RGB distance from the paper colour, 0..441
  // Solid: ink away from the paper and from enclosed paper (whose antialiased rim is a blend too).
  std::vector<uint8_t> ink(n), enclosed(n), solid(n);
  for (size_t i = 0; i < n; ++i) {
    ink[i] = shape[i] && (rgbAt(image, i) - colour).norm() > inkDistance;
    enclosed[i] = shape[i] && !ink[i];
  }
  const std::vector<uint8_t> nearEnclosed = dilate(enclosed, w, h, 1);
  for (size_t i = 0; i < n; ++i) solid[i] = ink[i] && !nearPaper[i] && !nearEnclosed[i];
  // An ink pixel nearer to enclosed paper (kept, opaque) than to the paper round the drawing is
  // blended with the former, as the inner side of a thin outline round a white belly: kept as
  // drawn, so the background does not show through between the line and the white.
  auto blendsWithEnclosed = [&](int x, int y) {
    int toPaper = kFringe + 1, toEnclosed = kFringe + 1;
    for (int dy = -kFringe; dy <= kFringe; ++dy)
      for (int dx = -kFringe; dx <= kFringe; ++dx) {
        const int u = x + dx, v = y + dy;
        if (u < 0 || u >= w || v < 0 || v >= h) continue;
        const size_t j = static_cast<size_t>(v) * w + u;
        const int r = std::max(std::abs(dx), std::abs(dy));
        if (paper.paper[j]) toPaper = std::min(toPaper, r);
        else if (enclosed[j]) toEnclosed = std::min(toEnclosed, r);
      }
    return toEnclosed < toPaper;
  };
  RgbaImage out = image;
  out.hasAlpha = true;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      uint8_t* o = out.at(x, y);
      const bool fringe = (ink[i] && nearPaper[i] && !blendsWithEnclosed(x, y)) || (paper.paper[i] && nearShape[i]);
      if (!fringe) {
        if (paper.paper[i]) o[0] = paper.colour[0], o[1] = paper.colour[1], o[2] = paper.colour[2], o[3] = 0;
        continue;
      }
      const Rgb p = rgbAt(image, i), d = p - colour;
      // The nearest solid ink colour c that p is a blend of with the paper: p = paper + a (c - paper).
      double best = 1e300, alpha = -1;
      Rgb inkColour = p;
      for (int dy = -kSearch; dy <= kSearch; ++dy)
        for (int dx = -kSearch; dx <= kSearch; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u < 0 || u >= w || v < 0 || v >= h || !solid[static_cast<size_t>(v) * w + u]) continue;
          const Rgb c = rgbAt(image, static_cast<size_t>(v) * w + u), e = c - colour;
          const double a = std::clamp(d.dot(e) / e.squaredNorm(), 0.0, 1.0);
          const double residual = (d - a * e).norm();
          const double score = residual + 0.5 * std::hypot(dx, dy);  // RGB units; nearer wins a near tie
          if (residual <= 8 + 0.1 * d.norm() && score < best) best = score, alpha = a, inkColour = c;
        }
      if (alpha < 0) {  // no solid ink explains it (a thin line): colour-to-alpha
        alpha = colourToAlpha(p, colour);
        inkColour = alpha > 0 ? Rgb(colour + d / alpha) : colour;
      } else if (alpha >= 0.25) {
        inkColour = colour + d / alpha;  // un-blend p itself: over the paper it looks as drawn
      }  // fainter pixels take the solid colour: un-blending would magnify their rounding 4x and more
      for (int c = 0; c < 3; ++c) o[c] = static_cast<uint8_t>(std::lround(std::clamp(inkColour[c], 0.0, 255.0)));
      const double original = image.hasAlpha ? image.at(x, y)[3] / 255.0 : 1.0;
      o[3] = static_cast<uint8_t>(std::lround(255 * alpha * original));
    }
  return out;
}

}  // namespace ib
