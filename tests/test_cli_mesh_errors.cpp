// `inbetween mesh` on the generated bad scenes (testkit/example_scenes.h, writeBadScenes), one per
// kind of mistake: each exits 2, prints nothing on stdout, and says on stderr, after
// "inbetween: ", which scene, key, feature, cut or field is wrong, and where the keys' topology
// differs, what to draw to fix it.
#include "cli_support.h"

#include <catch2/catch.hpp>
#include <string>

using Catch::Contains;
using Catch::Matches;
using Catch::StartsWith;
using test::badScene;
using test::CommandRun;
using test::inbetween;

namespace {

// `inbetween mesh SCENE`, whose output would go beside SCENE, in this process's scratch folder.
CommandRun mesh(const std::string& scene) { return inbetween({"mesh", scene}); }

}  // namespace

TEST_CASE("cli: mesh with a missing scene exits 2") {
  const CommandRun run = mesh(test::scratchPath("no-such-scene.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: ") && Contains("no-such-scene.json: cannot open"));
}

TEST_CASE("cli: mesh with a missing drawing exits 2") {
  const CommandRun run = mesh(badScene("missing-drawing.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: missing-drawing.json: key \"square\": drawing ") && Contains("no-such-drawing.png"));
}

TEST_CASE("cli: mesh with a missing drawing leaves no folder it created for -o") {
  const std::string folder = test::scratchPath("mesh-fail-folder");
  const CommandRun run = inbetween({"mesh", badScene("missing-drawing.json"), "-o", folder + "/deep/out.ibmesh"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK_THAT(run.err, StartsWith("inbetween: ") && Contains("no-such-drawing.png"));
  CHECK_FALSE(test::exists(folder));
}

TEST_CASE("cli: mesh with a corrupt PNG exits 2") {
  const CommandRun run = mesh(badScene("corrupt-png.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: corrupt-png.json: key \"square\": drawing ") && Contains("corrupt.png: not a readable PNG"));
}

TEST_CASE("cli: mesh with an empty drawing exits 2") {
  const CommandRun run = mesh(badScene("empty-drawing.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: empty-drawing.json: key \"square\": ") && Contains("empty.png: empty drawing"));
}

TEST_CASE("cli: mesh with malformed JSON exits 2") {
  const CommandRun run = mesh(badScene("malformed-json.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: malformed-json.json: malformed JSON"));
}

TEST_CASE("cli: mesh with an unknown field exits 2") {
  const CommandRun run = mesh(badScene("unknown-field.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: unknown-field.json: unknown field \"colour\" (expected one of: "));
}

TEST_CASE("cli: mesh with a missing feature exits 2") {
  const CommandRun run = mesh(badScene("missing-feature.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: missing-feature.json: ") && Contains("key \"arch\" does not place feature \"split.tip\""));
}

TEST_CASE("cli: mesh with a feature far off the shape exits 2") {
  const CommandRun run = mesh(badScene("feature-far-off.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Matches(R"(inbetween: feature-far-off\.json: key "arch": feature "top" .* px from the outline .*\n)"));
}

TEST_CASE("cli: mesh with a cut that leaves the shape exits 2") {
  const CommandRun run = mesh(badScene("cut-leaves-shape.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: cut-leaves-shape.json: key \"square\": cut \"split\": leaves the shape"));
}

TEST_CASE("cli: mesh with features in a different order exits 2") {
  const CommandRun run = mesh(badScene("loops-do-not-match.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Matches(R"(inbetween: loops-do-not-match\.json: outlines do not match: the piece around .* in key "arch" )"
                              R"(\(same features, different order\).*\n)"));
}

TEST_CASE("cli: mesh with a timeline naming no key exits 2") {
  const CommandRun run = mesh(badScene("timeline-unknown-key.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: timeline-unknown-key.json: timeline: mark 1: key: \"circle\" is not a key"));
}

TEST_CASE("cli: mesh with dynamics out of range exits 2") {
  const CommandRun run = mesh(badScene("dynamics-out-of-range.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: dynamics-out-of-range.json: dynamics: epsilon: 3 is out of range [0, 1]"));
}

TEST_CASE("cli: mesh with a missing stiffness image exits 2") {
  const CommandRun run = mesh(badScene("missing-stiffness-image.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: ") && Contains("no-such-stiffness.png: cannot open"));
}

TEST_CASE("cli: mesh with an extra hole in one key names the key, where the hole is and the cuts that fix it") {
  const CommandRun run = mesh(badScene("extra-hole.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Matches(R"(inbetween: extra-hole\.json: outlines do not match: key "other" has a hole that key "square" does not .*: )"
                              R"(hole around \(64, 64\), 400 px.*draw a "slit" cut in key "square".*draw a "split" cut in key "other")"
                              R"(.*When the keys' topology differs.*\n)"));
}

TEST_CASE("cli: mesh with an extra piece in one key names the key, where the piece is and the split that fixes it") {
  const CommandRun run = mesh(badScene("extra-piece.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Matches(R"(inbetween: extra-piece\.json: outlines do not match: key "other" has a piece that key "square" does not .*: )"
                              R"(piece around \(114, 16\), 256 px.*draw a "split" cut in key "square" where the pieces separate.*\n)"));
}

TEST_CASE("cli: mesh with a dotted plain feature says dots are reserved for cut features and what to rename it to") {
  const CommandRun run = mesh(badScene("dotted-feature.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: dotted-feature.json: key \"arch\": feature \"a.b\": names with a '.' are reserved for the "
                                 "features cuts create (CUT.left, CUT.right, CUT.tip") &&
                          Contains("rename it to \"a-b\""));
}

TEST_CASE("cli: mesh with an unknown field in a key names the key") {
  const CommandRun run = mesh(badScene("unknown-field-in-key.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: unknown-field-in-key.json: key \"arch\": unknown field \"colour\""));
}

TEST_CASE("cli: mesh with an unknown field in a cut names the key and the cut") {
  const CommandRun run = mesh(badScene("unknown-field-in-cut.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: unknown-field-in-cut.json: key \"square\": cut \"split\": unknown field \"width\""));
}

TEST_CASE("cli: mesh with an unknown field in a timeline mark names the mark") {
  const CommandRun run = mesh(badScene("unknown-field-in-mark.json"));
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: unknown-field-in-mark.json: timeline: mark 1: unknown field \"easing\""));
}
