// welded_frames SCENE --mesh FILE OUT.json [--frames A:B]: the reference positions the export's
// client checks (tests/clients) compare against. Plays the scene's timeline exactly as
// `inbetween render` does (the frame stream of pipeline/scene_frames.h, the cuts welded at one
// target pixel per drawing pixel) and writes every frame's welded positions in
// drawing pixels:
//   {"shapeSize": s, "canvas": [W, H], "fps": f,
//    "frames": [{"index": i, "time": t, "weights": [w0, ...], "positions": [x0, y0, ...]}]}
// time is in seconds from frame A; weights are the keys' interpolation weights (for the cross-fade).
// Exit 2 with a message for bad input.
#include "animation/frame_stream.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "output/render_mesh.h"
#include "pipeline/key_drawings.h"
#include "pipeline/scene_frames.h"
#include "pipeline/scene_multimesh.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>

int main(int argc, char** argv) {
  const char* usage = "usage: welded_frames SCENE --mesh FILE OUT.json [--frames A:B]\n";
  std::string scenePath, meshPath, outPath;
  int first = 0, last = -1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--mesh" && i + 1 < argc) meshPath = argv[++i];
    else if (arg == "--frames" && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%d:%d", &first, &last) != 2) { std::fputs(usage, stderr); return 2; }
    } else if (scenePath.empty()) scenePath = arg;
    else if (outPath.empty()) outPath = arg;
    else { std::fputs(usage, stderr); return 2; }
  }
  if (scenePath.empty() || meshPath.empty() || outPath.empty()) { std::fputs(usage, stderr); return 2; }
  try {
    const ib::Scene scene = ib::loadScene(scenePath);
    ib::SceneMultimeshOptions options;
    options.meshFile = meshPath;
    const ib::SceneMultimesh built = ib::sceneMultimesh(scene, options);
    const ib::Multimesh& mesh = *built.multimesh;
    std::vector<ib::RgbaImage> drawings = ib::readKeyDrawings(scene);
    int canvasW = 0, canvasH = 0;
    for (const ib::RgbaImage& d : drawings) {
      canvasW = std::max(canvasW, d.width);
      canvasH = std::max(canvasH, d.height);
    }
    const ib::render::RenderMesh renderMesh = ib::render::renderMeshOf(mesh, std::move(drawings));
    ib::FrameStream stream = ib::sceneFrameStream(scene, mesh);
    if (last < 0) last = stream.frameCount() - 1;
    if (first < 0 || first > last || last >= stream.frameCount()) {
      std::fprintf(stderr, "welded_frames: --frames %d:%d: the timeline has frames 0..%d\n", first, last, stream.frameCount() - 1);
      return 2;
    }
    const double fps = scene.timeline.fps();
    nlohmann::json frames = nlohmann::json::array();
    while (!stream.done() && stream.nextFrame() <= last) {
      const ib::AnimationFrame frame = stream.next();
      if (frame.index < first) continue;
      const Eigen::MatrixX2d welded = ib::render::weldCuts(frame.x, renderMesh.cutSides, 1.0, {}, &frame.heldPairs).positions;
      std::vector<double> positions(2 * welded.rows());
      for (Eigen::Index v = 0; v < welded.rows(); ++v) {
        positions[2 * v] = welded(v, 0);
        positions[2 * v + 1] = welded(v, 1);
      }
      const std::vector<double> weights(frame.weights.data(), frame.weights.data() + frame.weights.size());
      frames.push_back({{"index", frame.index}, {"time", (frame.index - first) / fps}, {"weights", weights}, {"positions", positions}});
    }
    const nlohmann::json out = {{"shapeSize", stream.shapeSize()}, {"canvas", {canvasW, canvasH}}, {"fps", fps}, {"frames", frames}};
    std::ofstream file(outPath);
    file << out.dump() << '\n';
    if (!file) throw std::runtime_error("cannot write " + outPath);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "welded_frames: %s\n", e.what());
    return 2;
  }
  return 0;
}
