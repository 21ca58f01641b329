#include "playback/scene_reloader.h"

#include "playback/scene_files.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "multimesh/multimesh.h"
#include "multimesh/multimesh_io.h"
#include "meshing/previous_map.h"
#include "meshing/trace_cache.h"
#include "pipeline/key_drawings.h"
#include "scene/parameters.h"

#include <filesystem>
#include <mutex>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#include <nlohmann/json.hpp>
#include <thread>

namespace ib::play {

namespace fs = std::filesystem;

namespace {

constexpr int kRebuildNice = 10;  // the rebuild thread's nice value (0 normal, 19 lowest)

LoadedScene built(Scene scene, const SceneMultimeshOptions& options, const PipelineProgress& progress) {
  LoadedScene out;
  SceneMultimesh mesh = sceneMultimesh(scene, options, progress);
  out.mesh = mesh.multimesh;
  out.initial = mesh.initial ? mesh.initial : initialBeside(scene);
  out.drawings = readKeyDrawings(scene, options.traceCache);
  out.features = featureVertices(scene, *out.mesh);
  if (progress) progress("preparing the artwork", 1);
  out.render = playerRenderMesh(scene, *out.mesh, out.drawings, out.features);
  out.scene = std::move(scene);
  return out;
}

// A loaded scene with what decides whether the next load may keep its multimesh.
struct Loaded {
  std::shared_ptr<const LoadedScene> scene;
  std::string meshFields;              // meshFields() of its scene file
  std::vector<FileStamp> meshStamps;   // its meshFiles() as of before the build
  bool optimized = true;               // its multimesh went through Comesh (or came from a file)
};

// What a build loads: a scene file, or an editor's text for it (never from the cache, which is
// of the file), with Comesh Optimization or without (the initial map: a fraction of the time).
struct Job {
  std::string path;
  std::optional<std::string> text;
  bool comesh = true;
  int threads = 0;  // the build's most threads (0: all cores)
  int id = 0;       // LoadedScene::build of what it loads
};

// Thrown from a build's progress callback when a newer edit makes it moot.
struct BuildCancelled {};

// An editor's quick build (the initial map) runs at normal priority: it is short and the edit
// waits for it. Every other build runs below the window's and the solver's threads, taking the
// time they leave, so the picture keeps its frame rate meanwhile (a Linux thread's nice value is
// its own).
bool urgent(const Job& job) { return job.text && !job.comesh; }

// The last build's map as the start of the next's, matching keys by name and drawing; none when
// the reference key is another.
PreviousMap previousMap(const Scene& lastScene, const std::shared_ptr<const Multimesh>& lastMesh, const Scene& scene) {
  PreviousMap out;
  if (!lastMesh || lastScene.keys.size() != static_cast<size_t>(lastMesh->keyCount())) return out;
  if (lastScene.keys[static_cast<size_t>(lastScene.reference)].name != scene.keys[static_cast<size_t>(scene.reference)].name) return out;
  out.mesh = lastMesh;
  out.reference = lastScene.reference;
  for (const KeySpec& key : scene.keys) {
    int found = -1;
    for (size_t k = 0; k < lastScene.keys.size(); ++k)
      if (lastScene.keys[k].name == key.name && lastScene.keys[k].drawing == key.drawing) found = static_cast<int>(k);
    out.keyOf.push_back(found);
  }
  return out;
}

// Loads the job's scene, keeping `last`'s multimesh, drawings and features when only fields that
// do not shape the mesh changed and its drawings and stiffness image did not (null `last`: none).
Loaded load(const Job& job, const Loaded* last, TraceCache* traces, const PipelineProgress& progress) {
  std::error_code error;
  if (!job.text && fs::is_directory(job.path, error)) loadScene(job.path);  // throws, naming the scene file inside
  const std::string text = job.text ? *job.text : readFile(job.path);
  Scene scene = parseScene(text, job.path);
  Loaded out;
  out.meshFields = meshFields(text);
  out.meshStamps = stampAll(meshFiles(scene));
  if (last && last->scene && last->meshFields == out.meshFields && last->meshStamps == out.meshStamps &&
      (last->optimized || !job.comesh)) {
    LoadedScene kept = *last->scene;
    if (kept.scene.cutInk != scene.cutInk) kept.render = playerRenderMesh(scene, *kept.mesh, kept.drawings, kept.features);
    kept.scene = std::move(scene);
    kept.build = job.id;
    out.scene = std::make_shared<const LoadedScene>(std::move(kept));
    out.optimized = last->optimized;
  } else {
    SceneMultimeshOptions options;
    options.useCache = !job.text;
    options.comesh = job.comesh;
    options.threads = job.threads;
    options.traceCache = traces;
    // An edit's quick build, a preview: each key's map starts from the last scene's initial map
    // (built, or the file beside the scene, no older than its drawings: initialBeside). Its
    // triangles are much like the new mesh's; Comesh's are not, and carry folds over: without an
    // initial map, none.
    PreviousMap previous;
    if (urgent(job) && last && last->scene && last->scene->initial)
      previous = previousMap(last->scene->scene, last->scene->initial, scene);
    if (previous.mesh) options.previous = &previous;
    LoadedScene fresh = built(std::move(scene), options, progress);
    fresh.build = job.id;
    out.scene = std::make_shared<const LoadedScene>(std::move(fresh));
    out.optimized = job.comesh;
  }
  return out;
}

}  // namespace

std::shared_ptr<const render::RenderMesh> playerRenderMesh(const Scene& scene, const Multimesh& mesh,
                                                           const std::vector<RgbaImage>& drawings, std::vector<int> features) {
  render::RenderMesh out = render::renderMeshOf(mesh, drawings, std::move(features));
  if (!scene.cutInk) out.inks = {};
  out.texture = std::make_shared<const render::TextureLevels>(render::textureLevels(render::textureLayers(out)));
  return std::make_shared<const render::RenderMesh>(std::move(out));
}

LoadedScene loadPlayerScene(const std::string& scenePath, const PipelineProgress& progress) {
  return built(loadScene(scenePath), SceneMultimeshOptions{}, progress);
}

struct SceneReloader::State {
  // The caller's thread only.
  std::shared_ptr<const LoadedScene> current;
  std::string currentPath;
  std::thread thread;

  // Shared with the rebuild thread, under `mutex`.
  mutable std::mutex mutex;
  std::string watchedPath;                // the scene file poll() watches (current()'s, or the last good open())
  std::vector<std::string> watchedFiles;  // its files (sceneFiles)
  std::vector<FileStamp> stamps;          // watchedFiles as of the last build's start
  Loaded lastGood;                        // the last good load (taken or not)
  std::string buildingPath;               // the running build's scene file
  bool runningOptimizedText = false;      // the running build is an editor's text with Comesh
  bool runningUrgent = false;             // the running build is an editor's quick one (urgent())
  TraceCache traces;                      // the builds' thread only (one build at a time)
  bool running = false;
  bool queued = false;                    // another build after the running one
  Job queuedJob;
  bool stopping = false;                  // the destructor waits: no queued build starts
  bool cancel = false;                    // the running build stops at its next progress report
  std::shared_ptr<const LoadedScene> finished;  // a good build not yet taken
  std::string finishedPath;
  std::optional<std::string> error;       // a failed build's message not yet taken
  double progress = 1;
  std::string stage;

  int start(Job job);  // numbers the job, then launch(); returns its number
  void launch(Job job);  // on a new thread, or queued behind the running build
  // A build queued behind one that ran at low priority, which needs the normal one: it waits for
  // the caller's thread to start it on a thread of its own (a thread cannot lower its nice value
  // again without privileges). The caller's thread only.
  void launchHandedOff();
  int nextId = 1;     // the caller's thread only
  void run(Job job);
  bool changed() const;
};

int SceneReloader::State::start(Job job) {
  job.id = nextId++;
  const int id = job.id;
  launch(std::move(job));
  return id;
}

void SceneReloader::State::launch(Job job) {
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (running) {
      queued = true;
      queuedJob = std::move(job);
      return;
    }
    if (queued) {  // a handed-off job waits: it runs first, this one after it
      std::swap(job, queuedJob);
    }
    running = true;
    buildingPath = job.path;
    runningOptimizedText = job.text && job.comesh;
    runningUrgent = urgent(job);
    cancel = false;
    progress = 0;
    stage = "loading";
  }
  if (thread.joinable()) thread.join();  // finished: it cleared `running`
  thread = std::thread([this, job] { run(job); });
}

void SceneReloader::State::launchHandedOff() {
  Job job;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (running || !queued || stopping) return;
    queued = false;
    job = std::move(queuedJob);
  }
  launch(std::move(job));
}

void SceneReloader::State::run(Job job) {
  bool lowered = false;  // this thread's nice value was raised
  for (;;) {
    const std::string path = job.path;
    if (!urgent(job) && !lowered) lowered = setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kRebuildNice) == 0;
    std::vector<std::string> files;
    Loaded last;
    {
      std::lock_guard<std::mutex> lock(mutex);
      buildingPath = path;
      runningOptimizedText = job.text && job.comesh;
      runningUrgent = urgent(job);
      files = path == watchedPath ? watchedFiles : std::vector<std::string>{path};
      last = lastGood;
    }
    const std::vector<FileStamp> before = stampAll(files);
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (path == watchedPath) stamps = before;  // changes from now on start another build
    }
    std::optional<Loaded> result;
    std::string message;
    try {
      result = load(job, &last, &traces, [this](const std::string& what, double fraction) {
        std::lock_guard<std::mutex> lock(mutex);
        if (cancel) throw BuildCancelled{};
        stage = what;
        progress = fraction;
      });
    } catch (const BuildCancelled&) {
      message = "cancelled";
    } catch (const std::exception& e) {
      message = e.what();
    }
    std::lock_guard<std::mutex> lock(mutex);
    const bool cancelled = cancel;
    cancel = false;
    if (cancelled) {
      // Nothing to report: the queued build replaces it.
    } else if (result) {
      const std::vector<std::string> newFiles = sceneFiles(result->scene->scene);
      std::vector<FileStamp> after;
      for (const std::string& file : newFiles) {
        FileStamp s = stamp(file);
        for (const FileStamp& b : before)
          if (b.path == file) s = b;  // a change during the build is seen by the next poll()
        after.push_back(s);
      }
      watchedPath = path;
      watchedFiles = newFiles;
      stamps = std::move(after);
      finished = result->scene;
      finishedPath = path;
      lastGood = std::move(*result);
      error.reset();
    } else {
      error = message.empty() ? path + ": cannot be loaded" : message;
    }
    if (queued && !stopping && !(lowered && urgent(queuedJob))) {
      queued = false;
      job = std::move(queuedJob);
      runningOptimizedText = job.text && job.comesh;  // under the lock, before a rebuildFromText can look
      runningUrgent = urgent(job);
      progress = 0;
      stage = "loading";
      continue;
    }
    running = false;
    runningOptimizedText = false;
    runningUrgent = false;
    progress = 1;
    stage.clear();
    return;
  }
}

bool SceneReloader::State::changed() const {
  std::vector<FileStamp> known;
  {
    std::lock_guard<std::mutex> lock(mutex);
    known = stamps;
  }
  for (const FileStamp& s : known)
    if (!(stamp(s.path) == s)) return true;
  return false;
}

SceneReloader::SceneReloader(const std::string& scenePath, const PipelineProgress& progress)
    : state_(std::make_unique<State>()) {
  const FileStamp before = stamp(scenePath);
  state_->lastGood = load(Job{scenePath, std::nullopt, true}, nullptr, &state_->traces, progress);
  state_->current = state_->lastGood.scene;
  state_->currentPath = scenePath;
  state_->watchedPath = scenePath;
  state_->watchedFiles = sceneFiles(state_->current->scene);
  for (const std::string& file : state_->watchedFiles) state_->stamps.push_back(file == scenePath ? before : stamp(file));
}

SceneReloader::~SceneReloader() {
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    state_->stopping = true;
    state_->queued = false;
    state_->cancel = true;  // a running build stops at its next progress report
  }
  if (state_->thread.joinable()) state_->thread.join();
}

const LoadedScene& SceneReloader::current() const { return *state_->current; }
const std::string& SceneReloader::path() const { return state_->currentPath; }

void SceneReloader::poll() {
  std::string watched;
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    // Already queued, or opening another scene: a change to this one waits for that to end.
    if (state_->running && (state_->queued || state_->buildingPath != state_->watchedPath)) return;
    watched = state_->watchedPath;
  }
  if (state_->changed()) state_->start(Job{watched, std::nullopt, true});  // queued behind a running build
}

void SceneReloader::reloadNow() {
  std::string watched;
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    watched = state_->watchedPath;
  }
  state_->start(Job{watched, std::nullopt, true});
}

void SceneReloader::open(const std::string& scenePath) { state_->start(Job{scenePath, std::nullopt, true}); }

int SceneReloader::rebuildFromText(const std::string& text, bool comesh) {
  std::string watched;
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    watched = state_->watchedPath;
    // An optimized build of an older text is moot: the new text's initial map goes first.
    if (state_->running && state_->runningOptimizedText) state_->cancel = true;
  }
  // The optimized build on one thread: the other cores keep the window drawing and the frames
  // solving meanwhile.
  return state_->start(Job{watched, text, comesh, comesh ? 1 : 0});
}

bool SceneReloader::takeReloaded() {
  state_->launchHandedOff();
  std::lock_guard<std::mutex> lock(state_->mutex);
  if (!state_->finished) return false;
  state_->current = std::move(state_->finished);
  state_->currentPath = state_->finishedPath;
  return true;
}

std::optional<std::string> SceneReloader::takeError() {
  std::lock_guard<std::mutex> lock(state_->mutex);
  std::optional<std::string> out = std::move(state_->error);
  state_->error.reset();
  return out;
}

bool SceneReloader::busy() const {
  state_->launchHandedOff();  // a caller waiting for the builds to end starts a handed-off one
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->running || state_->queued;
}

bool SceneReloader::previewing() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return (state_->running && state_->runningUrgent) || (state_->queued && urgent(state_->queuedJob));
}

double SceneReloader::progress() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->progress;
}

std::string SceneReloader::stage() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->stage;
}

}  // namespace ib::play
