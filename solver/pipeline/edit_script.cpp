#include "pipeline/edit_script.h"

#include "core/error.h"
#include "core/png_image.h"
#include "meshing/key_shape.h"
#include "meshing/tracing.h"
#include "pipeline/key_outlines.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace ib {

namespace {

namespace fs = std::filesystem;

std::string pointText(const Eigen::Vector2d& p) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.1f, %.1f)", p.x(), p.y());
  return text;
}

}  // namespace

void applyEditScript(SceneDocument& doc, const std::vector<EditOp>& ops, const std::string& opsFile,
                     const EditScriptOptions& options) {
  if (doc.problem()) throw InputError(*doc.problem() + " (fix the scene before applying " + fs::path(opsFile).filename().string() + ")");
  const fs::path folder = fs::path(doc.path()).parent_path();
  KeyOutlines outlines(doc.scene());
  const std::string where = fs::path(opsFile).filename().string();
  for (const EditOp& op : ops) {
    const std::string which = where + ": operation " + std::to_string(op.index) + " (" + op.op + "): ";
    try {
      edit::SceneEdit e = op.edit;
      if (op.snapsToOutline) {
        auto& feature = std::get<edit::SetFeature>(e);
        const std::vector<Outline>* traced = outlines.of(feature.key);
        if (!traced) {
          doc.apply(e);  // no such key: the document's message (did you mean)
          continue;
        }
        const Eigen::Vector2d on = nearestOnOutlines(*traced, feature.at);
        const double distance = (on - feature.at).norm();
        if (distance > options.snapDistance) {
          char far[64];
          std::snprintf(far, sizeof far, "%.1f", distance);
          throw InputError("feature " + inQuotes(feature.name) + " at " + pointText(feature.at) + " is " + far +
                           " px from key " + inQuotes(feature.key) + "'s outline (its nearest point is " + pointText(on) +
                           "): place it within " + std::to_string(static_cast<int>(options.snapDistance)) + " px of the outline");
        }
        feature.at = on;
      }
      if (!op.assignment.empty()) doc.setFromText(op.assignment);
      else doc.apply(e);
      if (const auto* added = std::get_if<edit::AddKey>(&op.edit))
        outlines.add(added->name, fs::path(added->drawing).is_absolute() ? added->drawing : (folder / added->drawing).string());
      if (const auto* removed = std::get_if<edit::RemoveKey>(&op.edit)) outlines.remove(removed->name);
      if (const auto* swapped = std::get_if<edit::SetKeyDrawing>(&op.edit))
        outlines.add(swapped->key, fs::path(swapped->drawing).is_absolute() ? swapped->drawing : (folder / swapped->drawing).string());
    } catch (const InputError& e) {
      const std::string message = e.what();
      throw InputError(message.rfind(where + ": operation", 0) == 0 ? message : which + message);
    }
  }
  if (doc.problem()) throw InputError(where + ": after the operations, the scene does not load: " + *doc.problem());
  const Scene& scene = doc.scene();
  KeyShapeOptions shape;
  shape.snapDistance = options.snapDistance;
  for (int k = 0; k < static_cast<int>(scene.keys.size()); ++k) {
    try {
      buildKeyShape(scene, k, *outlines.of(scene.keys[k].name), shape);
    } catch (const InputError& e) {
      throw InputError(where + ": after the operations: " + e.what());
    }
  }
}

}  // namespace ib
