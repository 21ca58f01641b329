// The Comesh Optimization scenes of the paper's Figures 4, 10 and 18, drawn as polygons: pentagon
// to star (regular and thin-spoked), hexagon to a thin six-spoked star, square to hexagon.
#include "testkit/example_scenes.h"

#include "testkit/drawings.h"

#include <cmath>
#include <sstream>

namespace test {

namespace {

// Shapes are designed on a 128 px canvas and drawn at twice that, so that tracing keeps their
// symmetry to a fraction of a percent of their size.
constexpr int kSize = 128;     // design canvas
constexpr double kScale = 2;   // drawing px per design unit
constexpr int kDrawing = 256;  // px: kScale * kSize
constexpr double kPi = 3.14159265358979323846;

using Polygon = std::vector<std::array<double, 2>>;

// Inside test by crossings of a ray towards +x, in drawing pixels.
Inside polygon(Polygon corners) {
  return [corners = std::move(corners)](double px, double py) {
    const double x = px / kScale, y = py / kScale;
    bool inside = false;
    for (size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++) {
      const auto& a = corners[i];
      const auto& b = corners[j];
      if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0])) inside = !inside;
    }
    return inside;
  };
}

// A regular polygon with `count` corners about (64, 64), the first at angle `start` (degrees,
// y down), alternating between radius `outer` and `inner` when `inner` > 0 (a star with count/2 tips).
Polygon regular(int count, double outer, double inner, double start) {
  Polygon out;
  for (int i = 0; i < count; ++i) {
    const double r = (inner > 0 && i % 2 == 1) ? inner : outer, a = (start + 360.0 * i / count) * kPi / 180;
    out.push_back({64 + r * std::cos(a), 64 + r * std::sin(a)});
  }
  return out;
}

std::string point(const std::array<double, 2>& p) {
  std::ostringstream out;
  out.precision(6);
  out << "[" << kScale * p[0] << ", " << kScale * p[1] << "]";
  return out.str();
}

struct PolygonKey {
  std::string name;
  Polygon shape;
  Polygon features;  // "f0", "f1", ... in order
};

// A scene with one polygon drawing per key; the first key is the reference.
ExampleScene polygonScene(const std::string& name, const std::vector<PolygonKey>& keys) {
  ExampleScene out{name, "", {}};
  std::string list;
  for (size_t k = 0; k < keys.size(); ++k) {
    std::string features;
    for (size_t i = 0; i < keys[k].features.size(); ++i)
      features += (i ? ", " : "") + ("\"f" + std::to_string(i) + "\": ") + point(keys[k].features[i]);
    list += std::string(k ? ",\n" : "") + R"(    {"name": ")" + keys[k].name + R"(", "drawing": ")" + keys[k].name +
            R"(.png", "features": {)" + features + "}}";
    out.drawings.push_back({keys[k].name + ".png", drawShape(kDrawing, kDrawing, polygon(keys[k].shape))});
  }
  out.json = "{\n  \"version\": 1,\n  \"reference\": \"" + keys[0].name + "\",\n  \"edge_length\": 12,\n  \"keys\": [\n" +
             list + "\n  ]\n}\n";
  return out;
}

// Every `step`-th corner of a polygon.
Polygon corners(const Polygon& shape, int step) {
  Polygon out;
  for (size_t i = 0; i < shape.size(); i += step) out.push_back(shape[i]);
  return out;
}

ExampleScene star(const std::string& name, int tips, double polygonRadius, double inner) {
  const Polygon base = regular(tips, polygonRadius, 0, -90), spiky = regular(2 * tips, 56, inner, -90);
  return polygonScene(name, {{"polygon", base, base}, {"star", spiky, corners(spiky, 2)}});
}

ExampleScene squareHexagon() {
  const Polygon square = {{28, 28}, {100, 28}, {100, 100}, {28, 100}}, hexagon = regular(6, 48, 0, 0);
  const Polygon squareFeatures = {{100, 64}, {64, 100}, {28, 64}, {64, 28}};
  const Polygon hexagonFeatures = {hexagon[0], {64, 64 + 48 * std::sqrt(0.75)}, hexagon[3], {64, 64 - 48 * std::sqrt(0.75)}};
  return polygonScene("square-hexagon", {{"square", square, squareFeatures}, {"hexagon", hexagon, hexagonFeatures}});
}

}  // namespace

ExampleScene threeStars() {
  const Polygon base = regular(5, 44, 0, -90), star = regular(10, 56, 24, -90), thin = regular(10, 56, 16, -90);
  return polygonScene("three-stars",
                      {{"polygon", base, base}, {"star", star, corners(star, 2)}, {"thin", thin, corners(thin, 2)}});
}

ExampleScene starSequence() {
  const Polygon base = regular(5, 44, 0, -90);
  std::vector<PolygonKey> keys = {{"k00", base, base}};
  for (int k = 1; k < 16; ++k) {
    const Polygon shape = regular(10, 48 + 0.6 * k, 42 - 1.8 * k, -90);
    keys.push_back({(k < 10 ? "k0" : "k") + std::to_string(k), shape, corners(shape, 2)});
  }
  return polygonScene("star-sequence", keys);
}

std::vector<ExampleScene> comeshScenes() {
  return {star("pentagon-star", 5, 44, 24), star("pentagon-star-thin", 5, 44, 13), star("hexagon-star-thin", 6, 44, 14),
          squareHexagon()};
}

}  // namespace test
