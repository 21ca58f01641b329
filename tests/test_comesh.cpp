#include "comesh/comesh.h"
#include "interpolation/interpolator.h"
#include "meshing/multimesh_builder.h"
#include "multimesh/mesh_quality.h"
#include "multimesh/multimesh_io.h"
#include "testkit/drawings.h"
#include "testkit/example_scenes.h"
#include "testkit/shape_checks.h"
#include "testkit/shared_results.h"

#include <catch2/catch.hpp>
#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

using namespace ib;

namespace {

struct Optimized {
  Scene scene;
  BuiltScene built;
  Multimesh result;
  ComeshReport report;
};

Scene writeAndLoad(const test::ExampleScene& example, const std::string& folder) {
  test::writeScene(example, folder);
  return loadScene((std::filesystem::path(folder) / example.name / "scene.json").string());
}

// A Comesh result as bytes: the report's counts and energies on one line, then the multimesh
// file. Doubles are written with 17 digits, so they read back exactly.
std::string encodeReport(const ComeshReport& r, const Multimesh& result) {
  std::ostringstream line;
  line.precision(17);
  line << r.keys << ' ' << r.verticesIn << ' ' << r.verticesOut << ' ' << r.trianglesIn << ' ' << r.trianglesOut << ' '
       << r.cohesiveIn << ' ' << r.cohesiveOut << ' ' << r.outerIterations << ' ' << r.innerIterations << ' '
       << r.remesh.flips << ' ' << r.remesh.splits << ' ' << r.remesh.collapses << ' ' << r.remesh.flipSeconds << ' '
       << r.remesh.splitSeconds << ' ' << r.remesh.collapseSeconds << ' ' << r.energyIn << ' ' << r.energyOut << ' '
       << r.seconds << '\n';
  return line.str() + encodeMultimesh(result);
}

Multimesh decodeReport(const std::string& bytes, ComeshReport& r) {
  const size_t end = bytes.find('\n');
  std::istringstream line(bytes.substr(0, end));
  line >> r.keys >> r.verticesIn >> r.verticesOut >> r.trianglesIn >> r.trianglesOut >> r.cohesiveIn >> r.cohesiveOut >>
      r.outerIterations >> r.innerIterations >> r.remesh.flips >> r.remesh.splits >> r.remesh.collapses >>
      r.remesh.flipSeconds >> r.remesh.splitSeconds >> r.remesh.collapseSeconds >> r.energyIn >> r.energyOut >> r.seconds;
  return decodeMultimesh(bytes.substr(end + 1), "shared Comesh result");
}

// The Comesh scenes and the cell split, built once per test process and optimized once per build
// of the test program (test::sharedResult): four test cases read them.
const std::map<std::string, Optimized>& optimizedScenes() {
  static const auto all = [] {
    const std::string folder = test::scratchDirectory("comesh");
    std::vector<test::ExampleScene> examples = test::comeshScenes();
    for (const auto& example : test::goodScenes())
      if (example.name == "cell-split") examples.push_back(example);
    std::map<std::string, Optimized> out;
    for (const auto& example : examples) {
      const Scene scene = writeAndLoad(example, folder);
      BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
      ComeshReport report;
      const std::string bytes = test::sharedResult("comesh-" + example.name + ".ibmesh", [&] {
        ComeshReport computed;
        const Multimesh optimized = comeshOptimize(*built.multimesh, &built.boundary, ComeshOptions{}, &computed);
        return encodeReport(computed, optimized);
      });
      Multimesh result = decodeReport(bytes, report);
      out.emplace(example.name, Optimized{scene, std::move(built), std::move(result), report});
    }
    return out;
  }();
  return all;
}

double smallestAngleOverKeys(const MultimeshQuality& q) {
  double smallest = 180;
  for (const KeyQuality& k : q.keys) smallest = std::min(smallest, k.smallestAngle);
  return smallest;
}

// The mesh with its keys in a new order: key j of the result is key order[j] of `mesh`.
Multimesh reorderKeys(const Multimesh& mesh, const std::vector<int>& order) {
  Multimesh out(mesh.vertexCount(), mesh.triangles());
  for (int k : order) out.addKey(mesh.keyPositions(k), mesh.cohesivePairs(k), mesh.boundaryVertices(k));
  for (int t = 0; t < mesh.triangleCount(); ++t) out.setStiffness(t, mesh.stiffness(t));
  return out;
}

ComeshBoundary reorderKeys(const ComeshBoundary& boundary, const std::vector<int>& order) {
  ComeshBoundary out = boundary;
  for (size_t a = 0; a < boundary.closedIn.size(); ++a)
    for (size_t j = 0; j < order.size(); ++j) out.closedIn[a][j] = boundary.closedIn[a][order[j]];
  out.point = [boundary, order](int key, int arc, double u) { return boundary.point(order[key], arc, u); };
  out.chordDeviation = [boundary, order](int key, int arc, double u0, double u1, double u2) {
    return boundary.chordDeviation(order[key], arc, u0, u1, u2);
  };
  out.arcLength = [boundary, order](int key, int arc) { return boundary.arcLength(order[key], arc); };
  return out;
}

// Largest distance from a boundary vertex of one inbetween to the boundary of the other, both ways.
double boundaryDistance(const Multimesh& a, const Eigen::MatrixX2d& xa, const Multimesh& b, const Eigen::MatrixX2d& xb) {
  const auto edgesA = test::boundaryEdges(a), edgesB = test::boundaryEdges(b);
  double worst = 0;
  for (int v : test::meshBoundary(a)) worst = std::max(worst, test::distanceToBoundary(edgesB, xb, xa.row(v)));
  for (int v : test::meshBoundary(b)) worst = std::max(worst, test::distanceToBoundary(edgesA, xa, xb.row(v)));
  return worst;
}

Eigen::MatrixX2d inbetween(const Multimesh& mesh, const Eigen::VectorXd& w) {
  SolverOptions options;
  options.relativeTolerance = 1e-6;
  options.maxIterations = 2000;
  Interpolator interpolator(mesh, InterpolationParams{}, options);
  return interpolator.solve(w).x;
}

}  // namespace

TEST_CASE("comesh: maps and triangles improve on every Comesh scene (MIPS mean and max fall, smallest angle rises)") {
  for (const auto& [name, o] : optimizedScenes()) {
    INFO("scene " << name << ": " << o.report.innerIterations << " inner, " << o.report.outerIterations << " outer, "
                  << o.report.remesh.flips << " flips, " << o.report.remesh.splits << " splits, "
                  << o.report.remesh.collapses << " collapses");
    const MultimeshQuality before = measureQuality(*o.built.multimesh), after = measureQuality(o.result);
    for (size_t i = 0; i < before.maps.size(); ++i) {
      INFO("map " << before.maps[i].from << " -> " << before.maps[i].to);
      CHECK(after.maps[i].mipsMean < before.maps[i].mipsMean);
      CHECK(after.maps[i].mipsMax < before.maps[i].mipsMax);
    }
    CHECK(smallestAngleOverKeys(after) > smallestAngleOverKeys(before));
    CHECK(o.report.energyOut < o.report.energyIn);
  }
}

TEST_CASE("comesh: every triangle stays positive and every cohesive pair collocated in every key") {
  for (const auto& [name, o] : optimizedScenes()) {
    INFO("scene " << name);
    CHECK_NOTHROW(o.result.validate());
    const std::vector<Triangle> triangles = o.result.triangles();
    for (int k = 0; k < o.result.keyCount(); ++k) {
      const Eigen::MatrixX2d x = o.result.keyPositions(k);
      int inverted = 0;
      for (const Triangle& t : triangles) inverted += !(edgeMatrix(x, t).determinant() > 0);
      CHECK(inverted == 0);
      for (const CohesivePair& p : o.result.cohesivePairs(k)) {
        REQUIRE(x.row(p.a) == x.row(p.c));
        REQUIRE(x.row(p.b) == x.row(p.d));
      }
      CHECK(o.result.cohesivePairs(k).size() >= o.built.multimesh->cohesivePairs(k).size());
    }
  }
}

TEST_CASE("comesh: features stay put and boundary vertices stay on their key's outline within 0.5 px") {
  for (const auto& [name, o] : optimizedScenes()) {
    INFO("scene " << name);
    const Multimesh& initial = *o.built.multimesh;
    for (int k = 0; k < o.result.keyCount(); ++k) {
      INFO("key " << o.scene.keys[k].name);
      const Eigen::MatrixX2d x0 = initial.keyPositions(k), x = o.result.keyPositions(k);
      for (int v = 0; v < initial.vertexCount(); ++v) {
        if (o.built.boundary.arc[v] < 0 || o.built.boundary.u[v] != 0) continue;  // features and arc starts
        bool found = false;
        for (int w = 0; w < x.rows() && !found; ++w) found = x.row(w) == x0.row(v);
        CHECK(found);
      }
      double worst = 0;
      for (int v : test::meshBoundary(o.result))
        worst = std::max(worst, test::distanceToShape(o.built.shapes[k], x.row(v)));
      CHECK(worst <= 0.5);
    }
  }
}

TEST_CASE("comesh: a pentagon-to-star inbetween at w = (0.5, 0.5) keeps five-fold symmetry within 1% of its size") {
  const Optimized& o = optimizedScenes().at("pentagon-star");
  const Eigen::MatrixX2d x = inbetween(o.result, Eigen::Vector2d(0.5, 0.5));
  const std::vector<Triangle> triangles = o.result.triangles();
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double area = 0;
  for (const Triangle& t : triangles) {
    const double a = 0.5 * edgeMatrix(x, t).determinant();
    centre += a * (x.row(t[0]) + x.row(t[1]) + x.row(t[2])).transpose() / 3;
    area += a;
  }
  centre /= area;
  const auto edges = test::boundaryEdges(o.result);
  const double size = boundingDiagonal(x);
  for (int turn = 1; turn < 5; ++turn) {
    const double angle = turn * 2 * M_PI / 5;
    const Eigen::Matrix2d r = Eigen::Rotation2Dd(angle).toRotationMatrix();
    double worst = 0;
    for (int v : test::meshBoundary(o.result)) {
      const Eigen::Vector2d turned = centre + r * (x.row(v).transpose() - centre);
      worst = std::max(worst, test::distanceToBoundary(edges, x, turned));
    }
    INFO("rotation by " << 72 * turn << " degrees: boundary off by " << worst << " px of " << size);
    CHECK(worst <= 0.01 * size);
  }
}

TEST_CASE("comesh: the result does not depend on the order of keys in the cyclic MIPS sum") {
  const std::string folder = test::scratchDirectory("comesh-order");
  const Scene scene = writeAndLoad(test::threeStars(), folder);
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  const std::vector<int> order = {0, 2, 1};
  const Multimesh forward = comeshOptimize(*built.multimesh, &built.boundary, ComeshOptions{}, nullptr);
  const ComeshBoundary reorderedBoundary = reorderKeys(built.boundary, order);
  const Multimesh backward = comeshOptimize(reorderKeys(*built.multimesh, order), &reorderedBoundary, ComeshOptions{}, nullptr);
  const Multimesh backwardInSceneOrder = reorderKeys(backward, order);  // {0, 2, 1} is its own inverse
  const double size = boundingDiagonal(forward.keyPositions(0));
  for (const Eigen::Vector3d& w : std::vector<Eigen::Vector3d>{Eigen::Vector3d(1, 1, 1) / 3, Eigen::Vector3d(0.5, 0.5, 0), Eigen::Vector3d(0, 0.5, 0.5),
                                  Eigen::Vector3d(0.5, 0, 0.5)}) {
    const double apart = boundaryDistance(forward, inbetween(forward, w), backwardInSceneOrder,
                                          inbetween(backwardInSceneOrder, w));
    INFO("w = (" << w.transpose() << "): inbetweens " << apart << " px apart, shape size " << size);
    CHECK(apart <= 0.01 * size);
  }
  const MultimeshQuality a = measureQuality(forward), b = measureQuality(backwardInSceneOrder);
  for (int k = 0; k < 3; ++k) CHECK(std::abs(a.keys[k].meanSmallestAngle - b.keys[k].meanSmallestAngle) <= 2.0);
}

TEST_CASE("comesh: without boundary data the boundary stays where it is") {
  const std::string folder = test::scratchDirectory("comesh-fixed");
  const Scene scene = writeAndLoad(test::comeshScenes().front(), folder);
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  const Multimesh result = comeshOptimize(*built.multimesh, nullptr, ComeshOptions{}, nullptr);
  const auto before = test::meshBoundary(*built.multimesh), after = test::meshBoundary(result);
  REQUIRE(before.size() == after.size());
  for (int k = 0; k < result.keyCount(); ++k) {
    const Eigen::MatrixX2d x0 = built.multimesh->keyPositions(k), x = result.keyPositions(k);
    for (int v : before) {
      bool found = false;
      for (int w : after) found = found || x.row(w) == x0.row(v);
      CHECK(found);
    }
  }
}

TEST_CASE("comesh: with remeshing off, vertex steps alone keep the topology and lower the objective on every Comesh scene") {
  const std::string folder = test::scratchDirectory("comesh-steps");
  for (const auto& example : test::comeshScenes()) {
    INFO(example.name);
    const Scene scene = writeAndLoad(example, folder);
    const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
    ComeshOptions options;
    options.remesh = false;
    options.outerIterations = 5;
    ComeshReport report;
    const Multimesh result = comeshOptimize(*built.multimesh, &built.boundary, options, &report);
    CHECK(result.triangles() == built.multimesh->triangles());
    CHECK(report.remesh.flips + report.remesh.splits + report.remesh.collapses == 0);
    CHECK(report.energyOut < report.energyIn * (1 - 1e-4));
  }
}

TEST_CASE("comesh: the sweep rule stops no later than outer_tol alone, the smallest angle within 1.5 degrees of it (or over 20) and the share under 20 degrees within 3 points, on every Comesh scene") {
  for (const auto& [name, o] : optimizedScenes()) {
    ComeshOptions paperOnly;
    paperOnly.sweepTolerance = 0;
    ComeshReport report;
    const Multimesh reference = comeshOptimize(*o.built.multimesh, &o.built.boundary, paperOnly, &report);
    INFO("scene " << name << ": " << o.report.outerIterations << " sweeps against " << report.outerIterations);
    CHECK(o.report.outerIterations <= report.outerIterations);
    const MultimeshQuality ours = measureQuality(o.result), paper = measureQuality(reference);
    CHECK(smallestAngleOverKeys(ours) > std::min(smallestAngleOverKeys(paper) - 1.5, 20.0));
    // 3 points: with a boundary that follows every key's corners and curves, the full run goes on
    // thinning pentagon-star-thin's slivers a few at a time for 100 sweeps more (9.3% -> 6.5%).
    for (size_t k = 0; k < ours.keys.size(); ++k) CHECK(ours.keys[k].shareUnder20 < paper.keys[k].shareUnder20 + 0.03);
  }
}
