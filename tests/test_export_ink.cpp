// The glTF export draws an opened cut's edges with the drawing's outline ink (issue 46, item 3),
// as strips of the line's width along the cut's sides (export/ink_strips.h) in a node of their own
// that the shape's weights animation moves, the ink's alpha in COLOR_0 morph-target deltas. On the
// test scenes drawn inked (tests/topology). The browser check (tests/clients, drop-split) compares
// what three.js draws with `inbetween render`.
#include "animation/frame_stream.h"
#include "export/baked_animation.h"
#include "export/export_job.h"
#include "export/gltf_export.h"
#include "export/ink_strips.h"
#include "multimesh/multimesh.h"
#include "output/render_mesh.h"
#include "pipeline/key_drawings.h"
#include "pipeline/scene_frames.h"
#include "pipeline/scene_multimesh.h"
#include "scene/scene.h"

#include <catch2/catch.hpp>
#include <tiny_gltf.h>

#include <filesystem>
#include <unistd.h>

using namespace ib;
using namespace ib::gltf;
namespace fs = std::filesystem;

namespace {

const std::string kTopology = std::string(INBETWEEN_ASSETS) + "/../tests/topology/";

struct Inked {
  Scene scene;
  std::shared_ptr<const Multimesh> mesh;
  render::RenderMesh renderMesh;
  BakedAnimation baked;
};

// A tests/topology scene (initial map, no Comesh, for speed), every frame baked.
Inked bakeInked(const std::string& name) {
  Inked out;
  out.scene = loadScene(kTopology + name + "/scene.json");
  SceneMultimeshOptions options;
  options.useCache = false;
  options.comesh = false;
  out.mesh = sceneMultimesh(out.scene, options).multimesh;
  out.renderMesh = render::renderMeshOf(*out.mesh, readKeyDrawings(out.scene));
  FrameStream stream = sceneFrameStream(out.scene, *out.mesh);
  out.baked = bakeAnimation(stream, out.renderMesh.cutSides, {0, stream.frameCount() - 1});
  return out;
}

// Barycentric point-in-triangle test, inclusive, at positions x.
bool insideMesh(const Eigen::Vector2d& p, const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& x) {
  for (const Triangle& t : triangles) {
    const Eigen::Vector2d a = x.row(t[0]).transpose(), b = x.row(t[1]).transpose(), c = x.row(t[2]).transpose();
    const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
    const double d1 = cross(b - a, p - a), d2 = cross(c - b, p - b), d3 = cross(a - c, p - c);
    if ((d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0)) return true;
  }
  return false;
}

bool acceptImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

}  // namespace

TEST_CASE("export ink: strips lie inside the shape, the line's width from their side, fading in only while the cut is open") {
  for (const std::string name : {"drop-split", "ring-open", "chomp"}) {
    INFO(name);
    const Inked inked = bakeInked(name);
    const render::CutInks& inks = inked.renderMesh.inks;
    REQUIRE_FALSE(inks.sides.empty());
    const InkStrips strips = inkStripsOf(inks, inked.renderMesh.triangles);
    REQUIRE(strips.vertexCount() > 0);
    REQUIRE(strips.triangles.size() == 2 * inks.sides.size());
    int insideChecked = 0, inside = 0, openFrames = 0;
    for (size_t f = 0; f < inked.baked.frames.size(); ++f) {
      const Eigen::MatrixX2d& x = inked.baked.positions[f];
      const Eigen::MatrixX2d p = inkStripPositions(strips, inks, x);
      const std::vector<float> colour = inkStripColours(strips, inks, inked.baked.closure[f], inked.baked.weights[f]);
      const std::vector<double> open = render::openWeights(inks, inked.baked.weights[f]);
      float largest = 0;
      for (int v = 0; v < strips.vertexCount(); ++v) {
        const double width = inks.cuts[strips.cut[v]].ink.width;
        const Eigen::Vector2d offset = (p.row(v) - x.row(strips.source[v])).transpose();
        const double moved = offset.norm();
        Eigen::Vector2d normal(0, 0);  // the sides' summed inward normal at this frame
        for (int s : strips.inward[v]) {
          const Edge& e = inks.sides[s];
          const Eigen::Vector2d along = (x.row(e[1]) - x.row(e[0])).transpose();
          Eigen::Vector2d n(-along.y(), along.x());
          if (n.dot((x.row(inks.sideApex[s]) - x.row(e[0])).transpose()) < 0) n = -n;
          if (n.norm() > 0) normal += n.normalized();
        }
        if (strips.inward[v].empty() || normal.norm() < 1e-9) CHECK(moved == 0);  // on the side, or the faces' normals cancel
        else CHECK(offset.dot(normal.normalized()) == Approx(width).epsilon(1e-9));
        const float alpha = colour[4 * v + 3];
        CHECK(alpha >= 0);
        CHECK(alpha <= 1);
        if (open[strips.cut[v]] <= 1e-12 || open[strips.cut[v]] >= 1 - 1e-12) CHECK(alpha == 0);  // a key draws its own line
        largest = std::max(largest, alpha);
        // Half-way across the strip, at frames where its cut is apart there, is inside the shape
        // (but at a chain's end on the outline, where the strip's end runs along the outline).
        if (!strips.inward[v].empty() && strips.along[v].empty() && moved > 0 && alpha > 0.1f) {
          const Eigen::Vector2d half = 0.5 * (p.row(v) + x.row(strips.source[v])).transpose();
          ++insideChecked;
          inside += insideMesh(half, inked.renderMesh.triangles, x);
        }
      }
      openFrames += largest > 0.3f;
    }
    INFO(inside << " of " << insideChecked << " strip midpoints inside the shape; " << openFrames << " frames with ink");
    CHECK(openFrames >= 3);
    CHECK(inside == insideChecked);
  }
}

TEST_CASE("export ink: the ink node has the shape's morph targets and weights, COLOR_0 deltas, and is left out with cut_ink off") {
  const fs::path dir = fs::temp_directory_path() / ("inbetween-export-ink-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Inked inked = bakeInked("drop-split");
  ExportedScene exported;
  exported.name = "drop-split";
  for (const KeySpec& key : inked.scene.keys) exported.keyNames.push_back(key.name);
  exported.canvas = {inked.renderMesh.artwork[0].width, inked.renderMesh.artwork[0].height};
  for (const bool quantize : {false, true}) {
    INFO("quantize " << quantize);
    GltfExportOptions options;
    options.quantize = quantize;
    const std::string file = (dir / "ink.glb").string();
    writeGltf(inked.baked, inked.renderMesh, exported, options, file);
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&acceptImage, nullptr);
    std::string error, warning;
    REQUIRE(loader.LoadBinaryFromFile(&model, &error, &warning, file));
    REQUIRE(model.nodes.size() == 2);
    REQUIRE(model.scenes[0].nodes == std::vector<int>{0, 1});
    const tinygltf::Mesh& shape = model.meshes[model.nodes[0].mesh];
    const tinygltf::Mesh& ink = model.meshes[model.nodes[1].mesh];
    REQUIRE(ink.primitives.size() == 1);
    const tinygltf::Primitive& strip = ink.primitives[0];
    CHECK(strip.targets.size() == shape.primitives[0].targets.size());
    CHECK(strip.attributes.count("COLOR_0") == 1);
    for (const auto& target : strip.targets) CHECK(target.count("COLOR_0") == 1);
    // One drawing pixel in front of the shape, so clients sorting by distance draw it last.
    REQUIRE(model.nodes[1].translation.size() == 3);
    CHECK(model.nodes[1].translation[2] == Approx((model.nodes[0].translation.empty() ? 0.0 : model.nodes[0].translation[2]) + 0.01));
    int shapeSampler = -1, inkSampler = -1;
    for (const tinygltf::AnimationChannel& c : model.animations[0].channels)
      if (c.target_path == "weights") (c.target_node == 0 ? shapeSampler : inkSampler) = c.sampler;
    CHECK(shapeSampler >= 0);
    CHECK(inkSampler == shapeSampler);
  }
  // The scene's "cut_ink": false, through the export job as `inbetween export` runs it.
  Scene plainScene = inked.scene;
  plainScene.cutInk = false;
  ExportJobOptions job;
  job.frames = {0, plainScene.timeline.frameCount() - 1};
  job.name = "drop-split";
  exportAnimation(plainScene, *inked.mesh, readKeyDrawings(plainScene), (dir / "plain.glb").string(), job);
  tinygltf::Model plain;
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&acceptImage, nullptr);
  std::string error, warning;
  REQUIRE(loader.LoadBinaryFromFile(&plain, &error, &warning, (dir / "plain.glb").string()));
  CHECK(plain.nodes.size() == 1);
  fs::remove_all(dir);
}
