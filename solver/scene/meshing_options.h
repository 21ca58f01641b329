// How a scene asks for its drawings to be traced and their outlines matched: the "tracing" and
// "corners" fields (docs/scene-format.md). Plain option types, read by meshing/tracing.h and
// meshing/shared_boundary.h; here so that the scene need not include the meshing stage.
#pragma once

#include <array>
#include <optional>

namespace ib {

// Drawings traced by colour: which paper-coloured regions enclosed by the drawing are holes.
// kMarked: only those a key marks with a point (KeySpec::holes); the rest are part of the shape.
// kEnclosedPaper: every one (scene `tracing.holes: "enclosed-paper"`). See meshing/paper.h.
enum class PaperHoles { kMarked, kEnclosedPaper };

struct TracingOptions {
  double tolerance = 0.05;     // px: potrace's curve-joining tolerance and our flattening error
  double minArea = 16;        // px^2: components and holes with less area are specks, dropped
  int alphaThreshold = 128;   // with alpha: a pixel belongs to the shape when alpha >= this (1..255)
  // Without alpha: the background colour (RGB) and the RGB distance above which a pixel belongs
  // to the shape. Set background to use it even when the drawing has alpha.
  std::optional<std::array<int, 3>> background;  // default: white for drawings without alpha
  double colorThreshold = 64;                    // RGB distance in (0, 442]
  PaperHoles holes = PaperHoles::kMarked;        // default: enclosed paper is part of the shape
};

// How the shared boundary treats the keys' outline corners (meshing/shared_boundary.h); "corners" in the
// scene.
enum class CornerHandling {
  kPaired,    // "paired": corners that correspond in every key pair up like features
  kVertices,  // "vertices": those, and a vertex at every other corner of every key (held there only)
  kOff,       // "off": arc length between features only, as in the paper
};

// How the keys' outlines are matched between features and corners; "correspondence" in the scene.
enum class OutlineCorrespondence {
  kOutline,  // "outline": by arc length, as in the paper
  kArtwork,  // "artwork": by position and tangent (meshing/outline_matching.h), the inside anchored where the drawings agree
};

}  // namespace ib
