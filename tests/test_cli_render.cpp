// `inbetween render` on lavapipe (--device cpu) with the generated example scenes: the frames
// --frames asks for, each a PNG of --size, and the contact sheet with the frames and layout asked
// for; bad input and a missing Vulkan driver exit 2 with a message after "inbetween: ", leaving
// no folder the command created; odd input exits 0 with a note.
#include "cli_support.h"

#include "core/png_image.h"

#include <catch2/catch.hpp>
#include <cstdio>
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

// FOLDER/frame_NNNN.png, as render names frame `frame`.
std::string framePath(const std::string& folder, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "/frame_%04d.png", frame);
  return folder + name;
}

// Frames first..last of FOLDER are PNGs of width x height, frame last + 1 is not there, and the
// contact sheet is a PNG.
void checkFrames(const std::string& folder, int first, int last, int width, int height) {
  for (int f = first; f <= last; ++f) {
    INFO("frame " << f);
    REQUIRE(exists(framePath(folder, f)));
    const ib::RgbaImage frame = ib::readPng(framePath(folder, f));
    CHECK(frame.width == width);
    CHECK(frame.height == height);
  }
  CHECK_FALSE(exists(framePath(folder, last + 1)));
  REQUIRE(exists(folder + "/contact_sheet.png"));
  CHECK(ib::readPng(folder + "/contact_sheet.png").width > 0);
}

// A run that must exit 2 with nothing on stdout and a message starting "inbetween: ".
void checkRefused(const CommandRun& run) {
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: "));
}

}  // namespace

TEST_CASE("cli: render writes the asked frames and a contact sheet") {
  const std::string out = scratchPath("render-out");
  const CommandRun run = inbetween({"render", notch(), "-o", out, "--frames", "2:5", "--size", "96x64", "--no-comesh", "--validation",
                                    "--device", "cpu", "--wireframe", "--features", "--cohesive", "--onion", "1", "--background", "ffffff"});
  INFO(run.output);
  REQUIRE(run.code == 0);
  CHECK(run.err.empty());  // --validation: no validation message either
  checkFrames(out, 2, 5, 96, 64);
  CHECK_FALSE(exists(framePath(out, 1)));
}

TEST_CASE("cli: render --sampling nearest writes the asked frames") {
  const std::string out = scratchPath("render-nearest");
  const CommandRun run = inbetween({"render", notch(), "-o", out, "--frames", "0:1", "--size", "96x64", "--no-comesh", "--validation",
                                    "--device", "cpu", "--sampling", "nearest"});
  INFO(run.output);
  REQUIRE(run.code == 0);
  CHECK(run.err.empty());
  checkFrames(out, 0, 1, 96, 64);
}

TEST_CASE("cli: render --sheet-frames puts just those frames on the sheet, --sheet-columns to a row") {
  const std::string out = scratchPath("render-sheet");
  const CommandRun run = inbetween({"render", notch(), "-o", out, "--frames", "0:6", "--size", "96x64", "--no-comesh", "--device", "cpu",
                                    "--sheet-frames", "0,3,5", "--sheet-columns", "3"});
  INFO(run.output);
  REQUIRE(run.code == 0);
  checkFrames(out, 0, 6, 96, 64);
  // Three tiles in one row, each as wide as the frame (96 px, under the 240 px cap) at its aspect
  // ratio (64 px high), 4 px apart and around: 3 * 96 + 4 * 4 = 304 by 64 + 2 * 4 = 72.
  const ib::RgbaImage sheet = ib::readPng(out + "/contact_sheet.png");
  CHECK(sheet.width == 304);
  CHECK(sheet.height == 72);
}

TEST_CASE("cli: render with --sheet-frames outside --frames exits 2") {
  const CommandRun run = inbetween({"render", notch(), "-o", scratchPath("render-bad"), "--frames", "0:6", "--sheet-frames", "2,9"});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, Contains("--sheet-frames: frame 9 is not rendered (frames 0..6)"));
}

TEST_CASE("cli: render with --sheet-frames and --sheet-every exits 2") {
  const CommandRun run = inbetween({"render", notch(), "-o", scratchPath("render-bad"), "--sheet-frames", "2", "--sheet-every", "3"});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, Contains("--sheet-frames and --sheet-every") && Contains("give one"));
}

TEST_CASE("cli: render with a missing drawing exits 2") {
  const CommandRun run = inbetween({"render", test::badScene("missing-drawing.json"), "-o", scratchPath("render-bad")});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, Contains("no-such-drawing.png"));
}

TEST_CASE("cli: render with a malformed --size exits 2") {
  const CommandRun run = inbetween({"render", notch(), "-o", scratchPath("render-bad"), "--size", "12"});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, StartsWith("inbetween: --size: '12' is not WIDTHxHEIGHT"));
}

TEST_CASE("cli: render with --frames past the timeline exits 2") {
  const CommandRun run = inbetween({"render", notch(), "-o", scratchPath("render-bad"), "--frames", "3:400"});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, StartsWith("inbetween: --frames: the timeline has frames 0..47"));
}

TEST_CASE("cli: render with an unknown --sampling exits 2 and names the option") {
  const CommandRun run = inbetween({"render", notch(), "-o", scratchPath("render-bad"), "--sampling", "bilinear"});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, StartsWith("inbetween: --sampling: \"bilinear\" is not auto, linear or nearest (did you mean \"linear\""));
}

TEST_CASE("cli: render with a missing --mesh file exits 2") {
  const CommandRun run = inbetween({"render", notch(), "-o", scratchPath("render-bad"), "--mesh", scratchPath("no-such.ibmesh")});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, Contains("no-such.ibmesh: cannot open"));
}

TEST_CASE("cli: render without a Vulkan driver exits 2 and says so") {
  // The loader pointed at a driver manifest that is not there finds no driver.
  const CommandRun run = inbetween({"render", notch(), "-o", scratchPath("render-bad")},
                                   "env VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json");
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, StartsWith("inbetween: render: no usable Vulkan device"));
}

TEST_CASE("cli: render with a missing drawing names the scene and the key and leaves no folder") {
  const std::string folder = scratchPath("render-fail-drawing");
  const CommandRun run = inbetween({"render", test::badScene("missing-drawing.json"), "-o", folder + "/frames"});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, Matches(R"(inbetween: missing-drawing\.json: key "square": drawing .*no-such-drawing\.png.*\n)"));
  CHECK_FALSE(exists(folder));
}

TEST_CASE("cli: render with loops that do not match leaves no folder") {
  const std::string folder = scratchPath("render-fail-loops");
  const CommandRun run = inbetween({"render", test::badScene("loops-do-not-match.json"), "-o", folder + "/frames", "--device", "cpu"});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, StartsWith("inbetween: loops-do-not-match.json: outlines do not match"));
  CHECK_FALSE(exists(folder));
}

TEST_CASE("cli: render with a missing --mesh file leaves no folder") {
  const std::string folder = scratchPath("render-fail-mesh");
  const CommandRun run =
      inbetween({"render", notch(), "-o", folder + "/frames", "--device", "cpu", "--mesh", scratchPath("no-such.ibmesh")});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, Contains("no-such.ibmesh"));
  CHECK_FALSE(exists(folder));
}

TEST_CASE("cli: render with --frames past the timeline leaves no folder") {
  const std::string folder = scratchPath("render-fail-frames");
  const CommandRun run = inbetween({"render", notch(), "-o", folder + "/frames", "--frames", "3:400"});
  INFO(run.output);
  checkRefused(run);
  CHECK_THAT(run.err, StartsWith("inbetween: --frames: the timeline has frames 0..47"));
  CHECK_FALSE(exists(folder));
}

TEST_CASE("cli: render with keys on canvases of different sizes notes the canvas it uses") {
  const std::string out = scratchPath("render-canvas-sizes");
  const CommandRun run =
      inbetween({"render", test::badScene("canvas-sizes.json"), "-o", out, "--frames", "0:1", "--no-comesh", "--device", "cpu"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK_THAT(run.err, StartsWith("inbetween: note: canvas-sizes.json: keys have different canvas sizes ") &&
                          Contains("the renderer's canvas is the largest, 140x128"));
  // Without --size the frames are the canvas.
  checkFrames(out, 0, 1, 140, 128);
}

TEST_CASE("cli: render --canvas WxH+X+Y that cuts the shape off notes how many frames and which, and --canvas fit shows them whole") {
  const std::string cut = scratchPath("render-canvas-cut");
  const CommandRun run = inbetween({"render", notch(), "-o", cut, "--frames", "0:3", "--canvas", "48x40+20-4", "--no-comesh", "--device", "cpu"});
  INFO(run.output);
  REQUIRE(run.code == 0);
  checkFrames(cut, 0, 3, 48, 40);  // the canvas at one pixel per drawing pixel
  CHECK_THAT(run.err, Contains("4 of 4 frames reach past the canvas (frames 0-3)"));
  CHECK_THAT(run.err, Contains("--canvas fit"));

  const std::string fit = scratchPath("render-canvas-fit");
  const CommandRun fitted = inbetween({"render", notch(), "-o", fit, "--canvas", "fit", "--no-comesh", "--device", "cpu"});
  INFO(fitted.output);
  REQUIRE(fitted.code == 0);
  CHECK(fitted.err.empty());
  // Every frame whole: nothing drawn on the picture's border, something drawn inside.
  const ib::RgbaImage first = ib::readPng(framePath(fit, 0));
  for (int f = 0; exists(framePath(fit, f)); ++f) {
    const ib::RgbaImage frame = ib::readPng(framePath(fit, f));
    REQUIRE(frame.width == first.width);
    int border = 0, drawn = 0;
    for (int y = 0; y < frame.height; ++y)
      for (int x = 0; x < frame.width; ++x) {
        const bool edge = x == 0 || y == 0 || x == frame.width - 1 || y == frame.height - 1;
        (edge ? border : drawn) += frame.at(x, y)[3] > 0;
      }
    INFO("frame " << f);
    CHECK(border == 0);
    CHECK(drawn > 100);
  }
}

TEST_CASE("cli: render with a malformed --canvas exits 2 naming the option and its forms, and leaves no folder") {
  const std::string out = scratchPath("render-bad-canvas");
  for (const char* canvas : {"10x10", "big", "0x10+0+0", "10x10+0+0+0"}) {
    const CommandRun run = inbetween({"render", notch(), "-o", out, "--canvas", canvas, "--no-comesh", "--device", "cpu"});
    INFO(canvas << ": " << run.output);
    checkRefused(run);
    CHECK_THAT(run.err, Contains("--canvas"));
    CHECK_FALSE(exists(out));
  }
}
