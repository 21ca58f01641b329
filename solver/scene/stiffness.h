// What a scene paints as per-triangle stiffness kappa, the "stiffness" field (docs/scene-format.md,
// paper section 7.3): a grayscale image over one key, named polygons and named brush strokes
// with a kappa each.
// meshing/stiffness_paint.h paints them onto a multimesh.
#pragma once

#include "core/plane_geometry.h"

#include <string>
#include <vector>

namespace ib {

struct StiffnessRegion {
  std::string name;
  int key = 0;        // the key it is drawn over
  Polyline polygon;   // >= 3 points, that key's drawing pixels
  double kappa = 1;   // > 0
};

// px: the radii a stroke may have.
constexpr double kMinStrokeRadius = 0.5, kMaxStrokeRadius = 1e4;

// A brush stroke: every triangle within `radius` of the polyline takes `kappa`.
struct StiffnessStroke {
  std::string name;
  int key = 0;        // the key it is drawn over
  Polyline points;    // >= 1 point, that key's drawing pixels
  double radius = 4;  // px, in [kMinStrokeRadius, kMaxStrokeRadius]
  double kappa = 1;   // > 0
};

struct StiffnessPaint {
  double soft = 0.1;   // kappa of a black pixel, > 0; default 0.1
  double stiff = 10;   // kappa of a white pixel, > soft; default 10
  std::string image;   // path of the stiffness image (PNG); empty: none
  int imageKey = -1;   // the key the image is drawn over
  std::vector<StiffnessRegion> regions;  // applied after the image, later ones win
  std::vector<StiffnessStroke> strokes;  // applied after the regions, later ones win

  bool empty() const { return image.empty() && regions.empty() && strokes.empty(); }
};

}  // namespace ib
