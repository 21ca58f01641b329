// The scene file: key drawings and the annotations that tie them together (features, cuts),
// the reference key, the timeline's marks, stiffness painting, and the parameters (the target
// edge length, tracing, solver, timeline and dynamics fields: scene/parameters.h declares them).
// Format: docs/scene-format.md. Coordinates are drawing pixels, y down; paths are relative to
// the scene file.
#pragma once

#include "animation/dynamics.h"
#include "animation/timeline.h"
#include "core/plane_geometry.h"
#include "interpolation/interpolation_params.h"
#include "scene/meshing_options.h"
#include "scene/stiffness.h"

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ib {

// notch: from the outline into the shape (first point on the outline, last inside);
// split: from the outline to the outline; slit: inside the shape at both ends (a hole opens).
enum class CutKind { kNotch, kSplit, kSlit };

// A cohesive zone drawn in a key where the shape is closed along it.
struct CutSpec {
  std::string name;
  CutKind kind = CutKind::kNotch;
  Polyline points;  // >= 2, drawing pixels
  // This cut's own "release" in [0, 1] and "release_window" in (0, 1] (docs/scene-format.md, "Cut
  // timing"); absent: the scene's solver.release and solver.release_window. Keys that close the
  // same cut give the same values or none.
  std::optional<double> release = {}, releaseWindow = {};
};

// The features a cut creates at its ends, named after it (see docs/scene-format.md, "Features and cuts"):
// notch NAME.left, NAME.right (at the mouth, as seen walking into the shape), NAME.tip;
// split NAME.start.left, NAME.start.right, NAME.end.left, NAME.end.right; slit NAME.start, NAME.end.
std::vector<std::string> cutFeatureNames(const std::string& cut, CutKind kind);

// px: the radii an interior feature's disc may have.
constexpr double kMinInteriorRadius = 0.5, kMaxInteriorRadius = 1000;

struct KeySpec {
  std::string name;
  std::string drawing;                               // path, resolved against the scene's folder
  std::map<std::string, Eigen::Vector2d> features;   // placed by the author, drawing pixels
  std::vector<CutSpec> cuts;                         // cuts closed in this key
  // Points inside the shape that correspond across keys (an eye, a foot drawn over the body), kept
  // as mesh vertices at these positions in every key, drawing pixels; "interior_features" in the
  // scene. Every key places the same names (docs/scene-format.md, "Interior features").
  std::map<std::string, Eigen::Vector2d> interiorFeatures = {};
  // px: the radius of the disc round an interior feature that moves with it as one rigid piece
  // (an eye, a button: the detail stays whole instead of stretching round one pinned point); the
  // same in every key once parsed, absent for a plain point. "radius" of an interior feature.
  std::map<std::string, double> interiorRadii = {};
  // Drawings traced by colour: a point inside each enclosed paper region that is a hole (else
  // enclosed paper is part of the shape), drawing pixels; "holes" in the scene.
  Polyline holes = {};
};

// The timeline's own fields ("timeline": fps, loop, spacing); its marks are the scene's structure.
struct TimelineSettings {
  double fps = 24;      // frames per second. Default 24
  bool loop = false;    // the last mark repeats the first's pose; frames stop before it. Default off
  SegmentSpacing spacing = SegmentSpacing::kWeights;  // every segment's unless its mark says. Default weights
};

// How render, play and export filter the key drawings' texels, "sampling" in the scene: kLinear
// (trilinear, smooth line art), kNearest (magnified pixel art keeps hard pixel edges), or kAuto,
// nearest when every drawing is pixel art (pipeline/artwork_sampling.h). Default kAuto.
enum class ArtworkSampling { kAuto, kLinear, kNearest };

struct Scene {
  std::string file;                 // the scene file, as named in messages
  std::vector<KeySpec> keys;        // in file order; the cyclic order of the keys
  int reference = 0;                // index of the key that is triangulated
  // px: target edge length, "edge_length"; 0 (absent) follows the drawings' size
  // (meshing/mesh_size.h: sqrt(mean key area) / 16, in [1, 8] px). Default 0.
  double edgeLength = 0;
  // The size guard, "max_vertices": a build whose estimated vertex count exceeds it is refused
  // before meshing (meshing/mesh_size.h). Default 200,000: on the 2-core VM mapping a second key
  // of that size takes about 10 CPU minutes at 250 MB, Comesh minutes more (docs/drawings-to-multimesh.md).
  int maxVertices = 200000;
  // "corners": how the shared boundary treats the outlines' corners (meshing/outline_corners.h).
  // Default vertices.
  CornerHandling corners = CornerHandling::kVertices;
  // "correspondence": how the keys correspond between features and corners. Default outline.
  OutlineCorrespondence correspondence = OutlineCorrespondence::kOutline;
  ArtworkSampling sampling = ArtworkSampling::kAuto;  // "sampling": how front ends filter the drawings
  bool cutInk = true;  // "cut_ink": render, play and export draw an opening cut's edges with the drawings' outline ink
  TracingOptions tracing;
  InterpolationParams interpolation;  // "solver": lambda, tau, alpha, non_overlap, metric
  // "solver.kappa": the stiffness of every triangle not painted otherwise (eq. 16), painted into
  // the multimesh with the "stiffness" field. Default 1.
  double kappa = 1;
  TimelineSettings timelineSettings;  // "timeline": fps, loop, spacing
  Timeline timeline;                // its marks and settings; every key a second apart when it has no marks
  DynamicsParams dynamics;          // epsilon = 0 (off) when absent
  StiffnessPaint stiffness;         // nothing painted when absent
  // What the loader assumed about odd but accepted input (e.g. one key: a still), each naming the
  // file; front ends print them as notes. The library never prints them.
  std::vector<std::string> notes;

  int keyIndex(const std::string& name) const;  // -1 when absent
};

// Reads and validates a scene: every problem is an InputError naming the file, the field and the
// key, e.g. `walk.json: key "arch": cut "split": needs at least 2 points`. Drawings are not read.
Scene loadScene(const std::string& path);
// The scene file's text; InputError naming it when it cannot be read (a folder holding a
// scene.json: naming that file).
std::string readSceneFile(const std::string& path);
Scene parseScene(const std::string& text, const std::string& path);

}  // namespace ib
