// Saving the player's tuned parameters back into the scene file.
#pragma once

#include <string>

namespace ib::play {

class LiveParameters;  // live_parameters.h

// Writes the tuned solver (tau, alpha, lambda, non_overlap), dynamics (epsilon when on, 0 when
// off; mu, gravity, wind, anchor) and timing (fps) values back into the scene file, atomically
// (core/atomic_file.h), every other field, its value and the key order preserved. A saved field
// absent from the file is added only when its value differs from the format's default, so saving
// untouched values leaves the file's fields as they were (its layout becomes 2-space JSON).
//
// kappa_scale has no field of its own: it is baked into every stiffness the scene names, which
// scales the painted kappa of every triangle exactly (painting is multiplicative): solver.kappa,
// stiffness.range (written, from its default [0.1, 10] when absent, if the scene paints an image)
// and every stiffness.regions[].kappa are multiplied by it. After saving, the scene loads with
// kappa_scale 1 and the same stiffness. A scale of 1 leaves those fields untouched.
//
// InputError naming the file when it cannot be read, is not a JSON object, or cannot be written
// (the old file is then left as it was), and naming the field when a scaled kappa leaves the
// format's range (1e6).
void saveParameters(const std::string& scenePath, const LiveParameters& params, double fps);

}  // namespace ib::play
