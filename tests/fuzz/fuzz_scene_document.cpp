// libFuzzer target: scene.json text through the scene document (scene/scene_document.h) and the
// writer that keeps its layout (core/json_layout.h). For any text that opens as a document: the
// unedited document writes back its text byte for byte, and after each of a few edits its text
// parses to the document's JSON. Bad input must come back as InputError; anything else (another
// exception, a crash, a sanitizer finding, a broken property) is a bug. Seeds: every bundled scene.
#include "core/error.h"
#include "scene/scene_document.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

namespace {

// The document's text parses to its JSON; aborts (a finding) when it does not.
void checkText(const ib::SceneDocument& document) {
  const auto text = nlohmann::ordered_json::parse(document.text(), nullptr, false);
  if (text.is_discarded() || text != nlohmann::ordered_json::parse(document.json())) std::abort();
}

template <class Edit>
void tryEdit(ib::SceneDocument& document, const Edit& edit) {
  try {
    document.apply(edit);
  } catch (const ib::InputError&) {
    return;
  }
  checkText(document);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    ib::SceneDocument document = ib::SceneDocument::fromText(text, "/nonexistent/fuzz/scene.json");
    if (document.text() != text) std::abort();
    tryEdit(document, ib::edit::SetParameter{"tau", 1e-5});
    tryEdit(document, ib::edit::SetParameter{"gravity_y", 2});
    tryEdit(document, ib::edit::SetFeature{"a", "f", {1, 2}});
    tryEdit(document, ib::edit::AddKey{"fuzz-key", "fuzz.png", 0});
    tryEdit(document, ib::edit::AddMark{0.5, "fuzz-key"});
    tryEdit(document, ib::edit::RenameKey{"fuzz-key", "renamed"});
    tryEdit(document, ib::edit::RemoveKey{"renamed"});
    while (document.canUndo()) document.undo();
    if (document.text() != text) std::abort();
  } catch (const ib::InputError&) {
  }
  return 0;
}
