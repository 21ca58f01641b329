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

#include "meshing/tracing.h"
#include "multimesh/multimesh.h"

#include <string>
#include <vector>

namespace ib {

struct StiffnessRegion {
  std::string name;
  int key = 0;        // the key it is drawn over
  Polyline polygon;   // >= 3 points, that key's drawing pixels
  double kappa = 1;   // > 0
};

struct StiffnessPaint {
  double soft = 0.1;   // kappa of a black pixel, > 0; default 0.1
  double stiff = 10;   // kappa of a white pixel, > soft; default 10
  std::string image;   // path of the stiffness image (PNG); empty: none
  int imageKey = -1;   // the key the image is drawn over
  std::vector<StiffnessRegion> regions;

  bool empty() const { return image.empty() && regions.empty(); }
};

// Sets every triangle's kappa: `base` (the scene's kappa), then the image, then the regions. The
// multimesh's key positions must be in drawing pixels. Throws InputError naming the image when it
// cannot be read.
void paintStiffness(Multimesh& mesh, const StiffnessPaint& paint, double base);

}  // namespace ib
