// `inbetween export` on the generated example scenes: a .glb, a .gltf with its .bin beside it, and
// the folders -o names created; bad input exits 2 with a message after "inbetween: " and leaves
// no file or folder behind; one key exits 0 with a note.
#include "cli_support.h"

#include "core/atomic_file.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

using Catch::Contains;
using Catch::Matches;
using Catch::StartsWith;
using test::CommandRun;
using test::exists;
using test::inbetween;
using test::scratchPath;

namespace {

std::string notch() { return test::exampleScene("square-arch-notch"); }

// Whether `path` is a binary glTF: it starts with the magic "glTF".
bool isGlb(const std::string& path) { return ib::readFile(path).rfind("glTF", 0) == 0; }

}  // namespace

TEST_CASE("cli: export writes a .glb") {
  const std::string out = scratchPath("export-out/notch.glb");
  const CommandRun run = inbetween({"export", notch(), "-o", out, "--no-comesh", "--frames", "0:6"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK(run.err.empty());
  REQUIRE(exists(out));
  CHECK(isGlb(out));
}

TEST_CASE("cli: export writes a .gltf with its .bin beside it") {
  const std::string out = scratchPath("export-out/notch.gltf");
  const CommandRun run = inbetween({"export", notch(), "-o", out, "--no-comesh", "--frames", "0:6"});
  INFO(run.output);
  CHECK(run.code == 0);
  REQUIRE(exists(out));
  CHECK(exists(scratchPath("export-out/notch.bin")));
  // The JSON names the .bin as its buffer, by a path relative to itself.
  const nlohmann::json gltf = nlohmann::json::parse(ib::readFile(out));
  CHECK(gltf.at("buffers").at(0).at("uri") == "notch.bin");
}

TEST_CASE("cli: export --meshopt --max-error writes a .glb") {
  const std::string out = scratchPath("export-out/notch-small.glb");
  const CommandRun run = inbetween({"export", notch(), "-o", out, "--no-comesh", "--meshopt", "--max-error", "0.25"});
  INFO(run.output);
  CHECK(run.code == 0);
  REQUIRE(exists(out));
  CHECK(isGlb(out));
}

TEST_CASE("cli: export into missing folders creates them") {
  REQUIRE_FALSE(exists(scratchPath("export-new")));
  const std::string out = scratchPath("export-new/a/b/notch.glb");
  const CommandRun run = inbetween({"export", notch(), "-o", out, "--no-comesh", "--frames", "0:2"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK(exists(out));
}

TEST_CASE("cli: export to a name that is not .glb or .gltf exits 2 and writes nothing") {
  const std::string out = scratchPath("export-out/notch.png");
  const CommandRun run = inbetween({"export", notch(), "-o", out});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: -o ") && Contains("name the file .glb (binary glTF) or .gltf"));
  CHECK_FALSE(exists(out));
}

TEST_CASE("cli: export with a missing drawing exits 2 and leaves no folder") {
  const std::string folder = scratchPath("export-fail-drawing");
  const CommandRun run = inbetween({"export", test::badScene("missing-drawing.json"), "-o", folder + "/out.glb"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK_THAT(run.err, Matches(R"(inbetween: missing-drawing\.json: key "square": drawing .*no-such-drawing\.png: cannot open.*\n)"));
  CHECK_FALSE(exists(folder));
}

TEST_CASE("cli: export with --frames past the timeline exits 2 and leaves no folder") {
  const std::string folder = scratchPath("export-fail-frames");
  const CommandRun run = inbetween({"export", notch(), "-o", folder + "/out.glb", "--frames", "3:400"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK_THAT(run.err, StartsWith("inbetween: --frames: the timeline has frames 0..47, asked for 3..400"));
  CHECK_FALSE(exists(folder));
}

TEST_CASE("cli: export with --max-error 0 exits 2") {
  const std::string out = scratchPath("export-out/zero.glb");
  const CommandRun run = inbetween({"export", notch(), "-o", out, "--max-error", "0"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK_THAT(run.err, StartsWith("inbetween: --max-error: '0' is not a distance"));
  CHECK_FALSE(exists(out));
}

TEST_CASE("cli: export with --max-error below the quantization step exits 2 and writes nothing") {
  const std::string out = scratchPath("export-out/tiny.glb");
  const CommandRun run = inbetween({"export", notch(), "-o", out, "--no-comesh", "--meshopt", "--max-error", "1e-9"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK_THAT(run.err, StartsWith("inbetween: --max-error 1e-09: ") && Contains("(16-bit quantization)"));
  CHECK_FALSE(exists(out));
}

TEST_CASE("cli: export under a file where a folder should be exits 2") {
  const std::string scene = notch();
  const CommandRun run = inbetween({"export", scene, "-o", scene + "/out.glb", "--no-comesh"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK_THAT(run.err, StartsWith("inbetween: -o: cannot create the folder " + scene));
  CHECK(std::filesystem::is_regular_file(scene));  // left as it was, not replaced by a folder
}

TEST_CASE("cli: export with one key exits 0 with a note that the animation is a still") {
  const std::string out = scratchPath("export-out/one-key.glb");
  const CommandRun run = inbetween({"export", test::badScene("one-key.json"), "-o", out, "--no-comesh"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK_THAT(run.err, StartsWith("inbetween: note: one-key.json: one key (\"square\"): the animation is a still"));
  REQUIRE(exists(out));
  CHECK(isGlb(out));
}
