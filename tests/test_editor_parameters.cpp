// The player's Save parameters in edit mode (editor/editor_view.h): the live parameters go into the
// editor's document as edits (undoable) and the document into the file, so that the file and the
// document agree and a later save of the document does not write the old values back.
#include "editor/editor_session.h"
#include "editor/editor_view.h"
#include "player/player_session.h"
#include "scene/scene_document.h"
#include "testkit/drawings.h"

#include <catch2/catch.hpp>
#include <filesystem>

using namespace ib;
namespace fs = std::filesystem;

TEST_CASE("editor: Save parameters puts the live values into the document, as one undo step, and the file") {
  const fs::path folder = fs::path(test::scratchDirectory("editor-parameters")) / "square-hexagon";
  fs::copy(fs::path(INBETWEEN_ASSETS) / "square-hexagon", folder, fs::copy_options::recursive);
  const std::string file = (folder / "scene.json").string();
  editor::EditorSession editing(SceneDocument::load(file));
  play::PlayerSession session(std::make_unique<play::SceneReloader>(file), {});
  const double before = editing.document().parameter("lambda");
  {
    editor::EditorView view(editing, session);
    session.parameters().set("lambda", before * 4);
    session.parameters().set("alpha", 0.37);
    session.saveParameters();
    for (const auto& m : session.messages()) CHECK_FALSE(m.error);
    CHECK(editing.document().parameter("lambda") == before * 4);
    CHECK_FALSE(editing.document().modified());
    CHECK(SceneDocument::load(file).parameter("lambda") == before * 4);
    // The document's own save keeps it (it held the old value before: the file would lose it).
    editing.save();
    CHECK(SceneDocument::load(file).parameter("lambda") == before * 4);
    editing.undo();  // both values at once
    CHECK(editing.document().parameter("lambda") == before);
    CHECK(editing.document().parameter("alpha") != 0.37);
  }
  // Without the editor, the player saves into the file as before.
  session.parameters().set("lambda", before * 2);
  session.saveParameters();
  CHECK(SceneDocument::load(file).parameter("lambda") == before * 2);
}
