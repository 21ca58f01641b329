// Saving the player's tuned parameters back into the scene file.
#pragma once

#include <string>

namespace ib::play {

class LiveParameters;  // live_parameters.h

// Writes the tuned controls (LiveParameters::saveInto: every value that differs from the file's,
// kappa_scale scaled into every stiffness the scene names) and the transport's frame rate
// (timeline.fps) into the scene file through its document (scene/scene_document.h): every other
// field keeps its value, its place and its text, so the save is a small diff; written
// atomically. InputError naming the file when it cannot be read, is not a JSON object or cannot
// be written (the old file is then left as it was), and naming the field when a value leaves
// the format's range.
// The file is written before `params` counts its kappa_scale as saved.
void saveParameters(const std::string& scenePath, LiveParameters& params, double fps);

}  // namespace ib::play
