// The scene and its multimesh, reloaded in the background when its files change, for the player:
// edit a drawing or the scene file in another program and the player picks the new one up.
#pragma once

#include "core/png_image.h"
#include "output/render_mesh.h"
#include "pipeline/scene_multimesh.h"
#include "scene/scene.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ib::play {

struct LoadedScene {
  Scene scene;
  std::shared_ptr<const Multimesh> mesh;     // optimized when built (or the current cache beside the scene); never null
  std::shared_ptr<const Multimesh> initial;  // the initial map when known (a built one, or NAME.initial.ibmesh
                                             // beside the scene), else null
  std::vector<RgbaImage> drawings;           // [key]
  std::vector<int> features;                 // featureVertices(scene, *mesh)
  std::shared_ptr<const render::RenderMesh> render;  // playerRenderMesh of mesh, made with it (off the
                                                     // window's thread for a rebuild); never null
  int build = 0;                             // which request loaded it (SceneReloader::rebuildFromText); 0: the first
};

// What the player draws of `mesh` (the scene's multimesh or its initial map): renderMeshOf with
// `features`, without the cuts' outline ink when the scene turns it off, its texture levels made.
std::shared_ptr<const render::RenderMesh> playerRenderMesh(const Scene& scene, const Multimesh& mesh,
                                                           const std::vector<RgbaImage>& drawings, std::vector<int> features);

// Loads a scene: loadScene, sceneMultimesh (the cache when current), the drawings, the features
// and the render mesh. Throws InputError for a bad scene.
LoadedScene loadPlayerScene(const std::string& scenePath, const PipelineProgress& progress = nullptr);

class SceneReloader {
 public:
  // Loads the scene now on the caller's thread (InputError for a bad scene: the play command
  // exits 2), using pipeline/scene_multimesh.h (the cache when current), and records the files' times.
  // `progress` is called during this first load only; background rebuilds report through
  // progress() and stage().
  explicit SceneReloader(const std::string& scenePath, const PipelineProgress& progress = nullptr);
  // Cancels the running rebuild at its next progress report (Comesh reports every outer
  // iteration; tracing and mapping between keys) and joins its thread. A build queued is dropped.
  ~SceneReloader();
  SceneReloader(const SceneReloader&) = delete;
  SceneReloader& operator=(const SceneReloader&) = delete;

  const LoadedScene& current() const;  // the last good scene
  const std::string& path() const;     // the scene file current() or the rebuild under way is of

  // Checks the scene file, every drawing and the stiffness image for a change (mtime or size, or
  // appearing / disappearing) and, if one changed, starts a background rebuild (one at a time; a
  // change during a rebuild restarts after it). When only fields that do not shape the multimesh
  // changed (solver lambda, tau, alpha, non_overlap; dynamics; timeline: what saveParameters
  // writes, kappa_scale aside) and no drawing did, the reloaded scene keeps the multimesh,
  // drawings and features (the same objects) and is ready at once.
  void poll();
  void reloadNow();                          // the same, unconditionally (e.g. a dropped file: see open())
  void open(const std::string& scenePath);   // a different scene, loaded in the background
  // The watched scene as `text` says (an editor's document, not saved yet; drawings resolved from
  // the scene file's folder), built in the background without the cache beside the scene, with
  // drawings that did not change since an earlier build not traced again. `comesh` false builds
  // the initial map only (tens to hundreds of milliseconds for the bundled scenes, against
  // seconds with Comesh Optimization), on every core at normal priority: an edit waits for it.
  // `comesh` true runs on one thread at a lower priority, so the window keeps drawing and the
  // frames solving. Queued behind a running build, replacing one queued; a running optimized
  // build of an earlier text is cancelled (it reports nothing). Returns the request's number,
  // which the scene it loads carries (LoadedScene::build); requests are numbered in order.
  int rebuildFromText(const std::string& text, bool comesh);

  // A finished rebuild becomes current() here (on the caller's thread); returns true once per
  // swap. References from current() stay valid until then; the meshes are shared, so a renderer
  // or solve worker may keep the old ones alive past the swap.
  bool takeReloaded();
  // A failed rebuild's message, once; current() stays the last good scene. A failed open() keeps
  // watching the old scene.
  std::optional<std::string> takeError();

  bool busy() const;          // a rebuild is running or queued
  bool previewing() const;    // an editor's quick build (rebuildFromText without Comesh) is running or queued
  double progress() const;    // the running rebuild's fraction in [0, 1]; 1 when idle
  std::string stage() const;  // the running rebuild's stage, e.g. "tracing arch"; empty when idle

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ib::play
