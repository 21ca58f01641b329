#include "playback/scene_parameters.h"

#include "core/error.h"
#include "playback/live_parameters.h"
#include "scene/scene_document.h"

namespace ib::play {

void saveParameters(const std::string& scenePath, LiveParameters& params, double fps) {
  SceneDocument document = SceneDocument::load(scenePath);
  LiveParameters saved = params;  // counts kappa_scale as saved once the file is written
  try {
    saved.saveInto(document);
    if (document.parameter("fps") != fps) document.apply(edit::SetParameter{"fps", fps});
  } catch (const InputError& e) {
    throw InputError(scenePath + ": cannot save the parameters: " + e.what());
  }
  document.save();
  params = saved;
}

}  // namespace ib::play
