// The paper's examples with artwork (assets/, docs/gallery.md): each built from its drawings and
// optimized by Comesh, then checked for what it is there to show. The properties every bundled
// scene has (keys hit at their times, keys rendered as their drawings, glTF the validator passes)
// are checked over all of assets/ elsewhere.
#include "animation/frame_stream.h"
#include "core/plane_geometry.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "pipeline/scene_frames.h"
#include "pipeline/scene_multimesh.h"
#include "scene/scene.h"
#include "testkit/shared_results.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
#include <numeric>

using namespace ib;

namespace {

const std::vector<std::string> kExamples = {
    "arch-stretch", "arch-split", "star-regular", "star-hard3", "star-hard6", "circles-in-circles", "circles-open",
    "cell-splitting", "chinese-character", "walk-star", "stylized-walk", "growing-flower", "flying-bird",
    "continental-drift"};

std::string exampleFile(const std::string& name) { return std::string(INBETWEEN_ASSETS) + "/" + name + "/scene.json"; }

// Built from the drawings (no cache) with Comesh Optimization, once per example and build of this
// program (test::bundledMultimesh), read once per process.
const ::test::BundledBuild& optimized(const std::string& name) {
  static std::map<std::string, ::test::BundledBuild> built;
  auto found = built.find(name);
  if (found == built.end()) found = built.emplace(name, ::test::bundledMultimesh(loadScene(exampleFile(name)), name)).first;
  return found->second;
}

double signedArea(const Eigen::MatrixX2d& x, const Triangle& t) {
  return 0.5 * orient(x.row(t[0]).transpose(), x.row(t[1]).transpose(), x.row(t[2]).transpose());
}

// The mesh's pieces: vertices joined by triangles (cut sides are separate vertices, so a piece
// glued to another by a closed cut is still its own). [vertex]: piece index.
std::vector<int> pieces(const Multimesh& mesh, int* count) {
  std::vector<int> parent(mesh.vertexCount());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Triangle& t : mesh.triangles())
    for (int c = 1; c < 3; ++c) parent[root(t[c])] = root(t[0]);
  std::map<int, int> index;
  std::vector<int> piece(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) piece[v] = index.emplace(root(v), static_cast<int>(index.size())).first->second;
  *count = static_cast<int>(index.size());
  return piece;
}

// Boundary edges (one triangle only) of the mesh, each with its piece.
struct PieceEdge {
  int a, b, piece;
};
std::vector<PieceEdge> boundaryEdges(const Multimesh& mesh, const std::vector<int>& piece) {
  std::map<std::pair<int, int>, int> seen;
  for (const Triangle& t : mesh.triangles())
    for (int c = 0; c < 3; ++c) ++seen[std::minmax(t[c], t[(c + 1) % 3])];
  std::vector<PieceEdge> out;
  for (const auto& [edge, uses] : seen)
    if (uses == 1) out.push_back({edge.first, edge.second, piece[edge.first]});
  return out;
}

// Least distance between the boundary vertices of two different pieces at positions x (px).
double gapBetweenPieces(const Multimesh& mesh, const std::vector<int>& piece, const Eigen::MatrixX2d& x) {
  double gap = std::numeric_limits<double>::infinity();
  const std::vector<char>& boundary = mesh.onBoundary();
  for (int v = 0; v < mesh.vertexCount(); ++v)
    for (int w = v + 1; w < mesh.vertexCount() && boundary[v]; ++w)
      if (boundary[w] && piece[v] != piece[w]) gap = std::min(gap, (x.row(v) - x.row(w)).norm());
  return gap;
}

// Whether a boundary edge of one piece crosses one of another piece at positions x.
bool piecesCross(const std::vector<PieceEdge>& edges, const Eigen::MatrixX2d& x) {
  for (size_t i = 0; i < edges.size(); ++i)
    for (size_t j = i + 1; j < edges.size(); ++j) {
      const PieceEdge &e = edges[i], &f = edges[j];
      if (e.piece == f.piece) continue;
      if (segmentsMeet(x.row(e.a).transpose(), x.row(e.b).transpose(), x.row(f.a).transpose(), x.row(f.b).transpose()))
        return true;
    }
  return false;
}

// Every frame of the scene's timeline (dynamics included), played on `mesh` with `params`.
std::vector<AnimationFrame> play(const Scene& scene, const Multimesh& mesh, const InterpolationParams& params) {
  FrameStream stream(mesh, scene.timeline, params, SolverOptions{}, scene.dynamics);
  std::vector<AnimationFrame> frames;
  while (!stream.done()) frames.push_back(stream.next());
  return frames;
}

}  // namespace

TEST_CASE("examples: every example builds, and after Comesh no triangle is inverted or flat in any key") {
  for (const std::string& name : kExamples) {
    INFO("assets/" << name);
    REQUIRE(std::filesystem::exists(exampleFile(name)));
    const Multimesh& mesh = *optimized(name).multimesh;
    for (int k = 0; k < mesh.keyCount(); ++k) {
      const Eigen::MatrixX2d x = mesh.keyPositions(k);
      double smallest = std::numeric_limits<double>::infinity();
      for (const Triangle& t : mesh.triangles()) smallest = std::min(smallest, signedArea(x, t));
      INFO("key " << k << ": smallest triangle area " << smallest << " px^2");
      CHECK(smallest > 1e-3);
    }
  }
}

TEST_CASE("examples: cell-splitting's cells touch at the first key and are apart by 5% of the shape size at the last") {
  const Scene scene = loadScene(exampleFile("cell-splitting"));
  const Multimesh& mesh = *optimized("cell-splitting").multimesh;
  int count = 0;
  const std::vector<int> piece = pieces(mesh, &count);
  REQUIRE(count == 2);
  const std::vector<AnimationFrame> frames = play(scene, mesh, scene.interpolation);
  const FrameStream probe = sceneFrameStream(scene, mesh);
  const double size = probe.shapeSize();
  CHECK(gapBetweenPieces(mesh, piece, frames.front().x) < 1.0);
  CHECK(gapBetweenPieces(mesh, piece, mesh.keyPositions(mesh.keyCount() - 1)) > 0.05 * size);
  double widest = 0;
  for (const AnimationFrame& frame : frames) widest = std::max(widest, gapBetweenPieces(mesh, piece, frame.x));
  CHECK(widest > 0.05 * size);
}

TEST_CASE("examples: circles-in-circles keeps its circles apart in every frame with non-overlap, each frame converged and unfolded, and not without") {
  const Scene scene = loadScene(exampleFile("circles-in-circles"));
  REQUIRE(scene.interpolation.nonOverlap);
  const Multimesh& mesh = *optimized("circles-in-circles").multimesh;
  int count = 0;
  const std::vector<int> piece = pieces(mesh, &count);
  REQUIRE(count >= 2);
  const std::vector<PieceEdge> edges = boundaryEdges(mesh, piece);
  int crossing = 0;
  int unconverged = 0, folded = 0;
  std::string which;
  for (const AnimationFrame& frame : play(scene, mesh, scene.interpolation)) {
    crossing += piecesCross(edges, frame.x);
    unconverged += !frame.converged;
    if (!frame.converged) which += " " + std::to_string(frame.index) + " (" + std::to_string(frame.iterations) + " iterations)";
    for (const Triangle& t : mesh.triangles()) folded += signedArea(frame.x, t) <= 0;
  }
  CHECK(crossing == 0);
  INFO("unconverged frames:" << which);
  CHECK(unconverged == 0);
  CHECK(folded == 0);
  InterpolationParams without = scene.interpolation;
  without.nonOverlap = false;
  Scene plain = scene;
  plain.dynamics = DynamicsParams{};  // the plain interpolation: overlap comes from the keys alone
  int crossingWithout = 0;
  for (const AnimationFrame& frame : play(plain, mesh, without)) crossingWithout += piecesCross(edges, frame.x);
  CHECK(crossingWithout > 0);
}

TEST_CASE("examples: flying-bird stays full-bodied, no frame under 90% of the area interpolated between its keys") {
  const Scene scene = loadScene(exampleFile("flying-bird"));
  const Multimesh& mesh = *optimized("flying-bird").multimesh;
  std::vector<double> keyArea(mesh.keyCount(), 0);
  for (int k = 0; k < mesh.keyCount(); ++k) {
    const Eigen::MatrixX2d x = mesh.keyPositions(k);
    for (const Triangle& t : mesh.triangles()) keyArea[k] += signedArea(x, t);
  }
  double smallest = std::numeric_limits<double>::infinity();
  for (const AnimationFrame& frame : play(scene, mesh, scene.interpolation)) {
    double area = 0, expected = 0;
    for (const Triangle& t : mesh.triangles()) area += signedArea(frame.x, t);
    for (int k = 0; k < mesh.keyCount(); ++k) expected += frame.weights[k] * keyArea[k];
    smallest = std::min(smallest, area / expected);
  }
  CHECK(smallest >= 0.9);
}

namespace {

// Whether point p (px) lies in some triangle of the mesh at positions x.
bool covered(const Multimesh& mesh, const Eigen::MatrixX2d& x, const Eigen::Vector2d& p) {
  for (const Triangle& t : mesh.triangles()) {
    const Eigen::Vector2d a = x.row(t[0]), b = x.row(t[1]), c = x.row(t[2]);
    if (orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("examples: circles-open's ring is whole at its first frame and open across its cut at the open key's frame") {
  const Scene scene = loadScene(exampleFile("circles-open"));
  const Multimesh& mesh = *optimized("circles-open").multimesh;
  // The middle of the cut drawn in the ring, from its hole to its outline.
  const Polyline& cut = scene.keys[scene.keyIndex("ring")].cuts.at(0).points;
  const Eigen::Vector2d middle = 0.5 * (cut.front() + cut.back());
  const std::vector<AnimationFrame> frames = play(scene, mesh, scene.interpolation);
  CHECK(covered(mesh, frames.front().x, middle));
  const TimelineMark& open = scene.timeline.marks().at(1);
  REQUIRE(open.label == "open");
  const int at = static_cast<int>(std::lround((open.time - scene.timeline.start()) * scene.timeline.fps()));
  REQUIRE(at < static_cast<int>(frames.size()));
  CHECK_FALSE(covered(mesh, frames[at].x, middle));
}

TEST_CASE("examples: the note of a build that had to refine its mesh says at which edge length it was built and which key folded") {
  // No bundled or drawn scene needs a refinement since the boundary follows every key's corners
  // and curves (docs/drawings-to-multimesh.md), so the note is checked on what the builder reports.
  const std::string note = refinementNote("/a/b/scene.json", 4.0 / 1.5, {"at 6 px, key \"sprout\" folded near (265.0, 445.9)"});
  CHECK_THAT(note, Catch::Contains("scene.json: built at edge length 2.67 px, finer than asked") &&
                       Catch::Contains("failed at 6 px, key \"sprout\" folded near (265.0, 445.9)") &&
                       Catch::Contains("Set \"edge_length\" to 2.67") && !Catch::Contains("/a/b"));
  const std::string twice = refinementNote("scene.json", 4, {"at 9 px, key \"a\" folded near (1.0, 2.0)", "at 6 px, key \"b\" folded near (3.0, 4.0)"});
  CHECK_THAT(twice, Catch::Contains("(1.0, 2.0); then at 6 px, key \"b\""));
  // Every example builds at the edge length it asks for.
  for (const std::string& name : kExamples)
    for (const std::string& n : optimized(name).notes) CHECK_THAT(n, !Catch::Contains("finer than asked"));
}
