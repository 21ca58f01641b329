// What the editor draws over each key, read from the document's JSON (so a document mid-edit, a
// feature placed in one key so far, still shows everything): features, interior features, cuts,
// stiffness strokes; which features a key still lacks; and the traced outline cut into arcs
// between consecutive features, each arc coloured by the features it runs from and to (in the
// loop's direction, the same in every key: tracing orients loops alike), so the same arc has the
// same colour in every key and features in a different order stand out before
// anything is meshed. CPU only.
#pragma once

#include "meshing/tracing.h"

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace ib::editor {

struct CutMark {
  std::string name, kind;  // kind: "notch", "split" or "slit"
  Polyline points;         // drawing pixels
};

struct StrokeMark {
  std::string name, key;
  Polyline points;
  double radius = 4, kappa = 1;
};

struct KeyMarks {
  std::string name, drawing;  // drawing: as the file says (relative to the scene's folder)
  std::map<std::string, Eigen::Vector2d> features, interior;
  std::map<std::string, double> radii;  // interior features with a disc
  std::vector<CutMark> cuts;
};

struct DocumentMarks {
  std::vector<KeyMarks> keys;
  std::string reference;  // the reference key's name (the first key when the file does not say)
  std::vector<StrokeMark> strokes;
  std::vector<std::string> markEases;  // [timeline mark]: its "ease" (a name, or JSON text), "linear" when none
  int keyIndex(const std::string& name) const;  // -1 when none
};

// Reads the document's JSON (SceneDocument::json); fields of the wrong type are skipped (the
// document's own validation names them).
DocumentMarks marksOf(const std::string& json);

// A feature some key places and another key must place too, or a cut's feature (NAME.left, ...)
// in a key where the cut is open: what the editor asks for next ("place `top` in key `open`").
struct MissingFeature {
  std::string feature, key;
  bool interior = false;
};
// In key order, starting after key `after` (-1: from the first key), so the prompt moves on to
// the next key.
std::vector<MissingFeature> missingFeatures(const DocumentMarks& marks, int after = -1);

// A piece of an outline loop between two consecutive features on it (or the whole loop when it
// has fewer than two).
struct OutlineArc {
  std::string from, to;  // feature names at its ends; empty for a loop without two features
  Polyline points;       // drawing pixels, from `from` to `to` along the loop
  int colour = -1;       // index into the palette, the same for the same (from, to) in every key; -1: none
  bool unmatched = false;  // another key places both, but another of this key's features comes between
};

// The arcs of one key's outlines. `features`: its features (those farther than `onOutline` px
// from every loop are left out). `pairColour`: the colour of each (from, to), shared across keys
// (filled as new pairs are met).
std::vector<OutlineArc> outlineArcs(const std::vector<Outline>& outlines, const std::map<std::string, Eigen::Vector2d>& features,
                                    std::map<std::pair<std::string, std::string>, int>& pairColour, double onOutline = 3);

// Marks arcs from feature a to feature b where another key that places both has, after a, another
// of this key's features before b (the order round the outline differs), and returns a message
// naming them and the keys, empty when every key agrees. arcs[k]: outlineArcs of marks.keys[k].
std::string orderProblems(const DocumentMarks& marks, std::vector<std::vector<OutlineArc>>& arcs);

}  // namespace ib::editor
