// The typed edits of a scene document (scene/scene_document.h): each names what it changes by
// the scene's own names (keys, features, cuts, regions) and positions in drawing pixels. Every
// edit is undoable. "Every key" edits keep the scene's rule that all keys place the same
// features: a feature added to one key is a problem of the document (SceneDocument::problem)
// until the other keys place it too.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace ib::edit {

using Point = Eigen::Vector2d;
using Points = std::vector<Eigen::Vector2d>;

// Keys. index: the place in the key order (the cyclic order of the animation); -1 appends.
struct AddKey { std::string name, drawing; int index = -1; };
struct RemoveKey { std::string name; };          // its features, cuts and holes go with it; so do marks of it
struct RenameKey { std::string from, to; };      // everywhere the scene names it
struct MoveKey { std::string name; int index; };  // to that place in the key order
struct SetReference { std::string key; };        // the key that is triangulated ("reference")
struct SetKeyDrawing { std::string key, drawing; };  // another drawing for the key (a path as the file gives it)

// Features on the outline. Set adds the feature to the key or moves it there.
struct SetFeature { std::string key, name; Point at; };
struct RemoveFeature { std::string name, key; };  // key empty: from every key
struct RenameFeature { std::string from, to; };   // in every key

// Interior features; radius: px of the disc that moves with the point (none: a plain point).
struct SetInteriorFeature { std::string key, name; Point at; std::optional<double> radius = std::nullopt; };
struct RemoveInteriorFeature { std::string name, key; };  // key empty: from every key
struct RenameInteriorFeature { std::string from, to; };
// The disc's radius (px) in every key that gives the feature one, or the first key that places it
// when none does: the scene's rule is one radius, given once or the same wherever given.
struct SetInteriorRadius { std::string name; double radius = 0; };

// Cuts (kind "notch", "split" or "slit"), drawn in the keys where the shape is closed along them.
// Renaming or removing a cut does the same to the features it creates (NAME.left, ...) in the
// keys where it is open.
struct AddCut { std::string key, name, kind; Points points; };
struct RemoveCut { std::string name, key; };  // key empty: from every key, with its features
struct RenameCut { std::string from, to; };
struct MoveCutPoint { std::string key, cut; int index; Point at; };
struct InsertCutPoint { std::string key, cut; int index; Point at; };  // before point `index` (the count appends)
struct RemoveCutPoint { std::string key, cut; int index; };

// Holes of drawings on paper: a point inside each enclosed paper region that is a hole.
struct AddHole { std::string key; Point at; };
struct MoveHole { std::string key; int index; Point at; };
struct RemoveHole { std::string key; int index; };

// Stiffness painting: regions (polygons) and strokes (polylines with a radius), named.
struct AddStiffnessRegion { std::string name, key; Points polygon; double kappa; };
struct AddStiffnessStroke { std::string name, key; Points points; double radius, kappa; };
struct RemoveStiffness { std::string name; };                  // a region or a stroke
struct RenameStiffness { std::string from, to; };
struct MoveStiffnessPoint { std::string name; int index; Point at; };  // a polygon or stroke point
struct SetStiffnessKappa { std::string name; double kappa; };
// Multiplies every stiffness the scene names by `factor` > 0: solver.kappa, stiffness.range
// (written from its default [0.1, 10] when an image is painted without one) and every region's
// and stroke's kappa, which scales each triangle's painted kappa exactly (painting is
// multiplicative). InputError naming the field a factor takes past (0, 1e6].
struct ScaleStiffness { double factor; };

// Timeline marks, by index in time order. key or weights (relative, by key name): exactly one.
// ease: the mark's "ease" as JSON text (a name such as "ease-in-out", or {"cubic_bezier": [...]});
// empty: none (linear). The document's validation names a bad one.
struct AddMark {
  double time;
  std::string key;
  std::vector<std::pair<std::string, double>> weights = {};
  std::string ease = {};
};
struct MoveMark { int index; double time; };
struct RemoveMark { int index; };
struct SetMarkKey { int index; std::string key; };
// The mark's "ease" as JSON text, as AddMark's; empty: none (linear).
struct SetMarkEase { int index; std::string ease; };

// A cut's own "release" (in [0, 1]: the weight of the keys where it is open at which it lets go,
// docs/scene-format.md "Cut timing"), written in every key that draws the cut; none: the scene's.
struct SetCutRelease { std::string cut; std::optional<double> release; };

// A parameter of the table (scene/parameters.h), by name, to a value; Reset removes the field
// so that the default holds.
struct SetParameter { std::string name; double value; };
struct ResetParameter { std::string name; };

using SceneEdit =
    std::variant<AddKey, RemoveKey, RenameKey, MoveKey, SetReference, SetKeyDrawing, SetFeature, RemoveFeature, RenameFeature, SetInteriorFeature, SetInteriorRadius,
                 RemoveInteriorFeature, RenameInteriorFeature, AddCut, RemoveCut, RenameCut, MoveCutPoint, InsertCutPoint,
                 RemoveCutPoint, AddHole, MoveHole, RemoveHole, AddStiffnessRegion, AddStiffnessStroke, RemoveStiffness,
                 RenameStiffness, MoveStiffnessPoint, SetStiffnessKappa, ScaleStiffness, AddMark, MoveMark, RemoveMark, SetMarkKey,
                 SetMarkEase, SetCutRelease, SetParameter, ResetParameter>;

// What the edit does, for the undo list: `move feature "top" in key "arch"`.
std::string describe(const SceneEdit& edit);

}  // namespace ib::edit
