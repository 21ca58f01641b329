// Stiffness painting (paper section 7.3): per-triangle stiffness kappa (eq. 16) from the scene, so
// a region resists deformation more (larger kappa) or less. Two ways to paint, both drawn over one
// key in that key's drawing pixels:
//   - a grayscale image: white is `stiff`, black is `soft`, grey in between on a log scale
//     (kappa = soft (stiff / soft)^g for grey level g in [0, 1]); transparent pixels leave the
//     scene's kappa, partly transparent ones blend towards it (in log kappa);
//   - named polygons with a kappa each, applied after the image (later regions win).
// A triangle takes the mean log kappa of four samples in the painted key: its centroid and the
// midpoints between the centroid and its corners.
#pragma once

#include "multimesh/multimesh.h"
#include "scene/stiffness.h"

namespace ib {

// Sets every triangle's kappa: `base` (the scene's kappa), then the image, then the regions. The
// multimesh's key positions must be in drawing pixels. Throws InputError naming the image when it
// cannot be read.
void paintStiffness(Multimesh& mesh, const StiffnessPaint& paint, double base);

}  // namespace ib
