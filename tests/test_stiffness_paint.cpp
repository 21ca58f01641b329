#include "core/error.h"
#include "core/png_image.h"
#include "interpolation/interpolator.h"
#include "meshing/stiffness_paint.h"
#include "testkit/shape_checks.h"
#include "testkit/shape_generators.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace ib;

namespace {

// A 160 x 40 px strip, and the same strip with its right part swelling to twice the thickness
// between x = 60 and 100 px. The left part (x < 60 px) is the same in both keys, so any distortion
// it has in an inbetween is forced on it by the swelling next to it: stiffness resists exactly that.
struct SwellingStrip {
  GridMesh grid = rectangleGrid(41, 11, 160, 40);  // 4 px cells: x = 60 and 80 px are grid lines
  Multimesh mesh{static_cast<int>(grid.points.rows()), grid.triangles};
  std::vector<int> left;  // triangles with centroid at x < 60 px
  std::vector<int> half;  // triangles with centroid at x < 80 px

  SwellingStrip() {
    Eigen::MatrixX2d swollen = grid.points;
    for (Eigen::Index v = 0; v < swollen.rows(); ++v) {
      const double t = std::clamp((grid.points(v, 0) - 60) / 40, 0.0, 1.0);
      swollen(v, 1) = 20 + (grid.points(v, 1) - 20) * (1 + t * t * (3 - 2 * t));
    }
    mesh.addKey(grid.points, {}, grid.boundary);
    mesh.addKey(swollen, {}, grid.boundary);
    for (int k = 0; k < mesh.triangleCount(); ++k) {
      const auto& t = grid.triangles[k];
      const double centroid = (grid.points(t[0], 0) + grid.points(t[1], 0) + grid.points(t[2], 0)) / 3;
      if (centroid < 60) left.push_back(k);
      if (centroid < 80) half.push_back(k);
    }
  }
};

// Mean ARAP distortion of the left part at w = (0.5, 0.5).
double leftDistortion(const SwellingStrip& s, const Multimesh& mesh) {
  SolverOptions tight;
  tight.relativeTolerance = 1e-8;
  tight.maxIterations = 3000;
  const Eigen::Vector2d w(0.5, 0.5);
  const Eigen::MatrixX2d x = Interpolator(mesh, {}, tight).solve(w).x;
  double total = 0;
  for (int k : s.left) total += ::test::arapDistortion(mesh, x, w, k);
  return total / s.left.size();
}

// Left half white, right half transparent, drawn over key 0.
std::string leftHalfImage() {
  RgbaImage image;
  image.width = 160;
  image.height = 40;
  image.hasAlpha = true;
  image.pixels.assign(160 * 40 * 4, 0);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 80; ++x) std::fill(image.at(x, y), image.at(x, y) + 4, 255);
  const std::string path = (std::filesystem::temp_directory_path() / "inbetween-test-stiffness-left.png").string();
  writePng(path, image);
  return path;
}

}  // namespace

TEST_CASE("stiffness painting: regions and images set kappa where they are drawn and leave the rest") {
  SwellingStrip s;
  StiffnessPaint byRegion;
  byRegion.regions.push_back({"left", 0, {{-1, -1}, {80, -1}, {80, 41}, {-1, 41}}, 20});
  StiffnessPaint byImage;
  byImage.soft = 0.1;
  byImage.stiff = 20;
  byImage.image = leftHalfImage();
  byImage.imageKey = 0;
  for (const StiffnessPaint* paint : {&byRegion, &byImage}) {
    Multimesh mesh = s.mesh;
    paintStiffness(mesh, *paint, 1.5);
    int stiff = 0;
    for (int k = 0; k < mesh.triangleCount(); ++k) {
      const bool isLeft = std::count(s.half.begin(), s.half.end(), k) > 0;
      CHECK(mesh.stiffness(k) == Approx(isLeft ? 20 : 1.5).epsilon(1e-9));
      stiff += isLeft;
    }
    CHECK(stiff == mesh.triangleCount() / 2);
  }
  // Grey maps geometrically between soft and stiff: mid grey (128/255) lands near sqrt(0.1 * 20).
  RgbaImage grey;
  grey.width = grey.height = 200;
  grey.pixels.assign(200 * 200 * 4, 128);
  for (int p = 0; p < 200 * 200; ++p) grey.pixels[4 * p + 3] = 255;
  const std::string path = (std::filesystem::temp_directory_path() / "inbetween-test-stiffness-grey.png").string();
  writePng(path, grey);
  byImage.image = path;
  Multimesh mesh = s.mesh;
  paintStiffness(mesh, byImage, 1.5);
  CHECK(mesh.stiffness(0) == Approx(0.1 * std::pow(200.0, 128.0 / 255)).epsilon(1e-9));
}

TEST_CASE("stiffness painting: a region painted stiff deforms measurably less than the same region unpainted") {
  SwellingStrip s;
  StiffnessPaint paint;
  paint.regions.push_back({"left", 0, {{-1, -1}, {60, -1}, {60, 41}, {-1, 41}}, 20});
  Multimesh painted = s.mesh;
  paintStiffness(painted, paint, 1);
  const double before = leftDistortion(s, s.mesh), after = leftDistortion(s, painted);
  INFO("mean ARAP distortion of the left part: unpainted " << before << ", painted stiff " << after);
  CHECK(after < 0.7 * before);
}

TEST_CASE("stiffness painting: an unreadable image is an input error naming it") {
  SwellingStrip s;
  StiffnessPaint paint;
  paint.image = "/nonexistent/stiffness.png";
  paint.imageKey = 0;
  CHECK_THROWS_WITH(paintStiffness(s.mesh, paint, 1), Catch::Contains("/nonexistent/stiffness.png"));
}
