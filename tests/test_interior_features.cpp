// Interior features (scene field keys[].interior_features): points inside the shape that
// correspond across keys, kept as mesh vertices at every key's placement through the reference
// mesh, the maps onto the other keys and Comesh Optimization. The case is a body that stays put
// while a dark dot on it (an eye) moves from the left to the right between two keys: with the
// feature the dot's two drawings land on each other at mid-blend; without it they cross-fade
// apart.
#include "comesh/comesh.h"
#include "core/error.h"
#include "core/plane_geometry.h"
#include "interpolation/interpolator.h"
#include "meshing/multimesh_builder.h"
#include "pipeline/scene_multimesh.h"
#include "scene/scene.h"
#include "testkit/drawings.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace ib;

namespace {

constexpr int kSize = 160;                 // px: canvas width and height
const Eigen::Vector2d kDotA(55, 80);       // px: the dot's centre in key "a"
const Eigen::Vector2d kDotB(104, 86);      // px: in key "b"
constexpr double kDotRadius = 7;           // px

// Key drawing: an opaque yellow body (a disc, a little wider in key "b") with a dark dot on it;
// the dot is part of the shape (same alpha), only its colour differs.
RgbaImage keyDrawing(double bodyWidth, const Eigen::Vector2d& dot) {
  RgbaImage image;
  image.width = image.height = kSize;
  image.hasAlpha = true;
  image.pixels.assign(static_cast<size_t>(kSize) * kSize * 4, 0);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      int body = 0, ink = 0;  // 4 x 4 samples
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
          const double px = x + (i + 0.5) / 4, py = y + (j + 0.5) / 4;
          const double dx = (px - 80) / bodyWidth, dy = (py - 80) / 60;
          if (dx * dx + dy * dy >= 1) continue;
          ++body;
          ink += (Eigen::Vector2d(px, py) - dot).norm() < kDotRadius;
        }
      uint8_t* p = image.at(x, y);
      const double t = body ? double(ink) / body : 0;  // share of the covered part that is dot
      p[0] = static_cast<uint8_t>(250 * (1 - t) + 30 * t);
      p[1] = static_cast<uint8_t>(200 * (1 - t) + 30 * t);
      p[2] = static_cast<uint8_t>(40 * (1 - t) + 30 * t);
      p[3] = static_cast<uint8_t>(255 * body / 16);
    }
  return image;
}

std::string pointJson(const Eigen::Vector2d& p) {
  std::ostringstream out;
  out << "[" << p.x() << ", " << p.y() << "]";
  return out.str();
}

// Writes the two drawings and a scene whose keys place `interiorA` / `interiorB` (JSON object
// bodies, empty for none); returns the scene file.
std::string writeScene(const std::string& name, const std::string& interiorA, const std::string& interiorB) {
  static const std::string scratch = test::scratchDirectory("interior");  // made afresh once per process
  const std::filesystem::path folder = std::filesystem::path(scratch) / name;
  std::filesystem::create_directories(folder);
  writePng((folder / "a.png").string(), keyDrawing(60, kDotA));
  writePng((folder / "b.png").string(), keyDrawing(66, kDotB));
  const auto key = [](const std::string& k, const std::string& interior) {
    return "{\"name\": \"" + k + "\", \"drawing\": \"" + k + ".png\", \"features\": {\"top\": [80, 20]}" +
           (interior.empty() ? "" : ", \"interior_features\": {" + interior + "}") + "}";
  };
  const std::string file = (folder / "scene.json").string();
  std::ofstream(file) << "{\"version\": 1, \"keys\": [" << key("a", interiorA) << ", " << key("b", interiorB) << "]}";
  return file;
}

std::string withEye() { return writeScene("eye", "\"eye\": " + pointJson(kDotA), "\"eye\": " + pointJson(kDotB)); }

// Centre of the dark pixels of a key drawing (px): where the dot is drawn.
Eigen::Vector2d dotCentre(const RgbaImage& image) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double weight = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      const double dark = p[3] == 255 ? std::max(0.0, (250.0 - p[0]) / 220) : 0;
      sum += dark * Eigen::Vector2d(x + 0.5, y + 0.5);
      weight += dark;
    }
  return sum / weight;
}

// Where point p of key k's drawing is drawn in a frame with positions x: the renderer draws key
// k's artwork through its triangles, so p goes with its barycentric coordinates.
Eigen::Vector2d drawnAt(const Multimesh& mesh, int k, const Eigen::Vector2d& p, const Eigen::MatrixX2d& x) {
  const Eigen::MatrixX2d X = mesh.keyPositions(k);
  for (const Triangle& t : mesh.triangles()) {
    const Eigen::Vector2d a = X.row(t[0]), b = X.row(t[1]), c = X.row(t[2]);
    const double area = orient(a, b, c);
    const double la = orient(b, c, p) / area, lb = orient(c, a, p) / area, lc = 1 - la - lb;
    if (la >= -1e-12 && lb >= -1e-12 && lc >= -1e-12)
      return la * x.row(t[0]).transpose() + lb * x.row(t[1]).transpose() + lc * x.row(t[2]).transpose();
  }
  FAIL("point " << formatPoint(p) << " is in no triangle of key " << k);
  return p;
}

SceneMultimesh optimized(const Scene& scene) {
  SceneMultimeshOptions options;
  options.useCache = false;
  return sceneMultimesh(scene, options);
}

// The vertex at the interior feature, or -1: the one exactly at key 0's placement.
int vertexAt(const Multimesh& mesh, int k, const Eigen::Vector2d& p) {
  const Eigen::MatrixX2d X = mesh.keyPositions(k);
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if ((X.row(v).transpose() - p).norm() <= 1e-9) return v;
  return -1;
}

std::string buildError(const std::string& file) {
  try {
    buildMultimesh(loadScene(file), MultimeshBuildOptions{});
  } catch (const InputError& e) {
    return e.what();
  }
  return "(built)";
}

}  // namespace

TEST_CASE("interior features: one vertex sits exactly at each key's placement, in the initial map and after Comesh") {
  const Scene scene = loadScene(withEye());
  REQUIRE(scene.keys[1].interiorFeatures.at("eye") == kDotB);
  const SceneMultimesh built = optimized(scene);
  for (const Multimesh* mesh : {built.initial.get(), built.multimesh.get()}) {
    const int v = vertexAt(*mesh, 0, kDotA);
    REQUIRE(v >= 0);
    CHECK((mesh->keyPositions(1).row(v).transpose() - kDotB).norm() <= 1e-9);
    CHECK_FALSE(mesh->onBoundary()[v]);
    const std::vector<int> shown = featureVertices(scene, *mesh);  // what render --features draws
    CHECK(std::count(shown.begin(), shown.end(), v) == 1);
    CHECK(shown.size() == 2);  // "top" on the outline and "eye"
  }
  REQUIRE(built.comesh);  // Comesh ran (and remeshed round the vertex) and left it there
  CHECK(built.comesh->remesh.flips + built.comesh->remesh.splits + built.comesh->remesh.collapses > 0);
}

TEST_CASE("interior features: at equal weights the dot's two drawings land on each other and without the feature they ghost apart") {
  const std::string plainFile = writeScene("plain", "", "");
  const std::string eyeFile = withEye();
  const RgbaImage a = readPng((std::filesystem::path(eyeFile).parent_path() / "a.png").string());
  const RgbaImage b = readPng((std::filesystem::path(eyeFile).parent_path() / "b.png").string());
  const Eigen::Vector2d centreA = dotCentre(a), centreB = dotCentre(b);
  REQUIRE((centreA - kDotA).norm() < 0.05);
  REQUIRE((centreB - kDotB).norm() < 0.05);
  const Eigen::VectorXd half = Eigen::VectorXd::Constant(2, 0.5);
  double apart[2] = {0, 0};  // px: plain, with the eye
  for (int withFeature = 0; withFeature < 2; ++withFeature) {
    const Scene scene = loadScene(withFeature ? eyeFile : plainFile);
    const SceneMultimesh built = optimized(scene);
    const Multimesh& mesh = *built.multimesh;
    Interpolator solver(mesh, scene.interpolation, SolverOptions{});
    const InterpolationResult frame = solver.solve(half);
    REQUIRE(frame.converged);
    const Eigen::Vector2d drawnA = drawnAt(mesh, 0, centreA, frame.x), drawnB = drawnAt(mesh, 1, centreB, frame.x);
    apart[withFeature] = (drawnA - drawnB).norm();
    if (withFeature) {
      // The feature vertex itself goes half way from one placement to the other. Not exactly
      // along the straight line: the move shears the body round the dot, and the solver blends
      // each triangle's rotation and stretch, not positions (measured: 5.0 px off the straight
      // line on the 49 px move, half way along it to 1%).
      const int v = vertexAt(mesh, 0, kDotA);
      REQUIRE(v >= 0);
      const Eigen::Vector2d move = kDotB - kDotA, at = frame.x.row(v).transpose() - kDotA;
      const double along = at.dot(move) / move.squaredNorm();
      const double across = std::abs(orient(Eigen::Vector2d::Zero(), move, at)) / move.norm();
      INFO("feature vertex at mid-blend: " << along << " of the way along its move, " << across << " px off the line");
      CHECK(std::abs(along - 0.5) < 0.05);
      CHECK(across < 0.15 * move.norm());
    }
  }
  INFO("dot drawings apart at mid-blend: " << apart[0] << " px without the interior feature, " << apart[1] << " px with");
  CHECK(apart[1] < 1);
  CHECK(apart[0] > 30);  // measured 49.3 px, the dot's move: its two drawings sit side by side (0 with)
}

TEST_CASE("interior features: with a radius the dot moves as one piece, round at mid-blend, where a plain point stretches it") {
  // The dot's outline in each key (a circle of kDotRadius round its centre) as drawn at equal
  // weights: its largest over its smallest distance from the drawn centre, for both keys' drawings.
  const auto roundness = [](const Multimesh& mesh, const Eigen::MatrixX2d& x) {
    double worst = 1;
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector2d centre = k == 0 ? kDotA : kDotB, drawnCentre = drawnAt(mesh, k, centre, x);
      double nearest = INFINITY, farthest = 0;
      for (int j = 0; j < 36; ++j) {
        const double angle = 2 * M_PI * j / 36;
        const Eigen::Vector2d p = centre + kDotRadius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
        const double d = (drawnAt(mesh, k, p, x) - drawnCentre).norm();
        nearest = std::min(nearest, d);
        farthest = std::max(farthest, d);
      }
      worst = std::max(worst, farthest / nearest);
    }
    return worst;
  };
  const std::string disc = "{\"at\": " + pointJson(kDotA) + ", \"radius\": 8}";
  const std::string files[2] = {withEye(), writeScene("eye-disc", "\"eye\": " + disc, "\"eye\": " + pointJson(kDotB))};
  double ratio[2] = {0, 0};  // plain point, disc
  for (int withRadius = 0; withRadius < 2; ++withRadius) {
    const Scene scene = loadScene(files[withRadius]);
    CHECK(scene.keys[1].interiorRadii.count("eye") == static_cast<size_t>(withRadius));  // given in key a, held in b too
    const SceneMultimesh built = optimized(scene);
    const Multimesh& mesh = *built.multimesh;
    Interpolator solver(mesh, scene.interpolation, SolverOptions{});
    const InterpolationResult frame = solver.solve(Eigen::VectorXd::Constant(2, 0.5));
    REQUIRE(frame.converged);
    ratio[withRadius] = roundness(mesh, frame.x);
    if (withRadius) {  // every vertex of the disc is where it is in key a, moved by the dot's move
      const Eigen::MatrixX2d A = mesh.keyPositions(0), B = mesh.keyPositions(1);
      int ring = 0, inside = 0;
      for (int v = 0; v < mesh.vertexCount(); ++v) {
        const double r = (A.row(v).transpose() - kDotA).norm();
        if (r > 8 + 1e-9) continue;
        ring += r > 8 - 1e-9;
        ++inside;
        CHECK((B.row(v) - A.row(v) - (kDotB - kDotA).transpose()).norm() < 1e-9);
      }
      CHECK(ring >= 6);
      CHECK(inside > ring);
    }
  }
  INFO("dot at mid-blend, largest over smallest radius: " << ratio[0] << " as a point, " << ratio[1] << " with radius 8");
  CHECK(ratio[1] < 1.05);
  CHECK(ratio[0] > 1.1);  // measured 5.7 as a point, 1.01 with the radius
}

TEST_CASE("interior features: a radius that differs between keys, or discs that overlap, are input errors") {
  const std::string differ = "{\"at\": " + pointJson(kDotB) + ", \"radius\": 6}";
  CHECK_THROWS_WITH(loadScene(writeScene("radii", "\"eye\": {\"at\": " + pointJson(kDotA) + ", \"radius\": 8}", "\"eye\": " + differ)),
                    Catch::Contains("key \"b\": interior feature \"eye\": radius: is 6 here and 8 in key \"a\""));
  const std::string message =
      buildError(writeScene("discs", "\"eye\": {\"at\": [55, 80], \"radius\": 8}, \"nose\": [62, 80]",
                            "\"eye\": " + pointJson(kDotB) + ", \"nose\": [114, 86]"));
  CHECK_THAT(message, Catch::Contains("interior features \"eye\" and \"nose\" are less than 9 px apart"));
  CHECK_THAT(message, Catch::Contains("make their radii smaller"));
}

TEST_CASE("interior features: misplaced ones are input errors naming the key, the feature and what to do") {
  SECTION("outside the shape") {
    const std::string message = buildError(writeScene("outside", "\"eye\": [5, 5]", "\"eye\": " + pointJson(kDotB)));
    CHECK_THAT(message, Catch::Contains("key \"a\": interior feature \"eye\" at (5.0, 5.0) lies outside the drawn shape"));
    CHECK_THAT(message, Catch::Contains("\"features\" entry"));
  }
  SECTION("too close to the outline") {
    const std::string message = buildError(writeScene("close", "\"eye\": " + pointJson(kDotA), "\"eye\": [142, 80]"));
    // Key b's body reaches x = 146 on the feature's row: 4 px away (the traced outline is on the
    // drawing's antialiased edge).
    CHECK_THAT(message, Catch::Contains("key \"b\": interior feature \"eye\" at (142.0, 80.0) is 4 px from the outline or a cut"));
    CHECK_THAT(message, Catch::Contains("move it further inside"));
  }
  SECTION("placed by one key only") {
    const std::string file = writeScene("one-key", "\"eye\": " + pointJson(kDotA), "");
    CHECK_THROWS_WITH(loadScene(file), Catch::Contains("key \"b\": does not place interior feature \"eye\" (key \"a\" does)"));
  }
  SECTION("named like a feature on the outline") {
    const std::string file = writeScene("clash", "\"top\": " + pointJson(kDotA), "\"top\": " + pointJson(kDotB));
    CHECK_THROWS_WITH(loadScene(file), Catch::Contains("interior feature \"top\" has the name of a feature"));
  }
}
