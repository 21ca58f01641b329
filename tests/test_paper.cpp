// Drawings on paper (meshing/paper.h): the paper is the background connected to the canvas
// border; white regions the drawing encloses are shape unless marked as holes; the artwork has
// the paper transparent and the outline's antialiasing un-blended into partly transparent ink.
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/png_image.h"
#include "meshing/multimesh_builder.h"
#include "meshing/paper.h"
#include "meshing/tracing.h"
#include "pipeline/key_drawings.h"
#include "scene/scene.h"
#include "testkit/drawings.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <png.h>

using namespace ib;

namespace {

using Rgb = std::array<int, 3>;
using Paint = std::function<Rgb(double x, double y)>;  // the colour at a point, drawing px

constexpr Rgb kPaper{255, 255, 255}, kBody{230, 120, 40}, kWhite{255, 255, 255}, kPupil{20, 20, 60};

// 128 x 128 on white paper: an orange body (disc r 45 at (64, 64)), a white belly (r 18 at
// (64, 76)), a white eye (r 8 at (48, 44)) with a dark pupil (r 3). Every white region but the
// paper is enclosed by the body.
Rgb character(double x, double y) {
  auto in = [&](double cx, double cy, double r) { return (x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r; };
  if (!in(64, 64, 45)) return kPaper;
  if (in(64, 76, 18)) return kWhite;
  if (in(48, 44, 3)) return kPupil;
  if (in(48, 44, 8)) return kWhite;
  return kBody;
}

// Coverage of the body's outer disc in pixel (x, y), by the same 4 x 4 samples the drawing uses.
double bodyCoverage(int x, int y) {
  int hits = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double u = x + (i + 0.5) / 4 - 64, v = y + (j + 0.5) / 4 - 64;
      hits += u * u + v * v < 45 * 45;
    }
  return hits / 16.0;
}

// An opaque drawing without alpha: the paint averaged over 4 x 4 samples per pixel (antialiased
// as a scan or an export on paper is).
RgbaImage onPaper(int width, int height, const Paint& paint) {
  RgbaImage image;
  image.width = width, image.height = height, image.hasAlpha = false;
  image.pixels.assign(static_cast<size_t>(width) * height * 4, 255);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      int sum[3] = {0, 0, 0};
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
          const Rgb c = paint(x + (i + 0.5) / 4, y + (j + 0.5) / 4);
          for (int k = 0; k < 3; ++k) sum[k] += c[k];
        }
      for (int k = 0; k < 3; ++k) image.at(x, y)[k] = static_cast<uint8_t>(std::lround(sum[k] / 16.0));
    }
  return image;
}

// The image as an RGB PNG, no alpha channel (as a scanner writes it).
void writeRgbPng(const std::string& path, const RgbaImage& image) {
  std::vector<uint8_t> rgb;
  for (size_t i = 0; i < image.pixels.size(); ++i)
    if (i % 4 != 3) rgb.push_back(image.pixels[i]);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  REQUIRE(png_image_write_to_file(&png, path.c_str(), 0, rgb.data(), 0, nullptr));
}

std::vector<Outline> trace(const RgbaImage& image, const TracingOptions& options, const Polyline& holes = {}) {
  return traceOutlines(shapeMask(image, options, holes, "drawing.png"), options, "drawing.png");
}

RgbaImage artwork(const RgbaImage& image, const TracingOptions& options, const Polyline& holes = {}) {
  return paperToAlpha(image, findPaper(image, options, holes, "drawing.png"));
}

// Pixels a renderer would show as a light fringe: nearly opaque (alpha >= 128) yet at least 60
// RGB units lighter than the body towards the paper (distance from the body colour > 60 and
// closer to white than the body is).
int fringePixels(const RgbaImage& image) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double c = bodyCoverage(x, y);
      if (c <= 0 || c >= 1) continue;  // only the outline's pixels
      const uint8_t* p = image.at(x, y);
      double d = 0;
      for (int k = 0; k < 3; ++k) d += double(p[k] - kBody[k]) * (p[k] - kBody[k]);
      if ((!image.hasAlpha || p[3] >= 128) && std::sqrt(d) > 60) ++count;
    }
  return count;
}

}  // namespace

TEST_CASE("paper: white regions the drawing encloses are part of the shape, the paper round it is not") {
  const RgbaImage drawing = onPaper(128, 128, character);
  const auto outlines = trace(drawing, {});
  REQUIRE(outlines.size() == 1);
  CHECK(outlines[0].holes.empty());  // no hole through the belly or the eye
  CHECK(loopArea(outlines[0].outer) == Approx(M_PI * 45 * 45).epsilon(0.01));
}

TEST_CASE("paper: the artwork is transparent outside, opaque inside, and its outline partly transparent ink") {
  const RgbaImage drawing = onPaper(128, 128, character);
  const RgbaImage art = artwork(drawing, {});
  CHECK(art.hasAlpha);
  CHECK(art.at(3, 3)[3] == 0);                // paper
  CHECK(art.at(64, 127)[3] == 0);
  const uint8_t* belly = art.at(64, 76);      // enclosed white: kept, opaque white
  CHECK((belly[0] == 255 && belly[1] == 255 && belly[2] == 255 && belly[3] == 255));
  const uint8_t* eye = art.at(52, 44);
  CHECK((eye[0] == 255 && eye[3] == 255));
  const uint8_t* body = art.at(64, 30);
  CHECK((body[0] == kBody[0] && body[1] == kBody[1] && body[2] == kBody[2] && body[3] == 255));
  // The outline's antialiased pixels: alpha within 0.02 of the body's coverage, colour within 3
  // RGB units of the body per channel where the coverage is 1/8 or more (measured: 0.004, 1).
  int edge = 0;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      const double c = bodyCoverage(x, y);
      if (c <= 0 || c >= 1) continue;
      const uint8_t* p = art.at(x, y);
      INFO("pixel (" << x << ", " << y << ") coverage " << c << ": " << int(p[0]) << " " << int(p[1]) << " "
                     << int(p[2]) << " alpha " << int(p[3]));
      CHECK(std::abs(p[3] / 255.0 - c) <= 0.02);
      if (c >= 0.125)
        for (int k = 0; k < 3; ++k) CHECK(std::abs(p[k] - kBody[k]) <= 3);
      ++edge;
    }
  CHECK(edge > 250);  // about 2 pi 45 = 283 partly covered pixels
  // A light fringe: the drawing as read has one on every partly covered outline pixel that is
  // mostly paper (200 of the 284); the artwork none.
  CHECK(fringePixels(drawing) > 100);
  CHECK(fringePixels(art) == 0);
}

TEST_CASE("paper: the artist can make enclosed paper a hole, every region or the marked ones") {
  const RgbaImage drawing = onPaper(128, 128, character);
  TracingOptions every;
  every.holes = PaperHoles::kEnclosedPaper;  // today's tracing: every enclosed white region a hole
  const auto all = trace(drawing, every);
  REQUIRE(all.size() == 2);         // the body and the pupil, an island in the eye's hole
  CHECK(all[0].holes.size() == 2);  // the belly and the eye's white
  CHECK(artwork(drawing, every).at(64, 76)[3] == 0);

  const Polyline bellyOnly{{64, 76}};  // a point inside the belly: that region, and only it, is a hole
  const auto marked = trace(drawing, {}, bellyOnly);
  REQUIRE(marked.size() == 1);
  REQUIRE(marked[0].holes.size() == 1);
  // The hole is traced where a pixel is within color_threshold 64 of white, about 3/4 covered by
  // the belly against orange, so its radius is about 0.4 px short: 5% of its area.
  CHECK(loopArea(marked[0].holes[0]) == Approx(-M_PI * 18 * 18).epsilon(0.06));
  const RgbaImage art = artwork(drawing, {}, bellyOnly);
  CHECK(art.at(64, 76)[3] == 0);
  CHECK(art.at(52, 44)[3] == 255);  // the eye stays
}

TEST_CASE("paper: a misplaced hole point is an input error saying where it is and what to do") {
  const RgbaImage drawing = onPaper(128, 128, character);
  CHECK_THROWS_WITH(trace(drawing, {}, {{64, 30}}), Catch::Contains("drawing.png: holes: point 1 [64, 30]") &&
                                                         Catch::Contains("on the drawing's ink"));
  CHECK_THROWS_WITH(trace(drawing, {}, {{64, 76}, {2, 2}}),
                    Catch::Contains("point 2 [2, 2]") && Catch::Contains("paper round the drawing"));
  CHECK_THROWS_WITH(trace(drawing, {}, {{200, 5}}), Catch::Contains("off the drawing (128 x 128 px)"));
  const RgbaImage alpha = test::drawShape(64, 64, test::disc(32, 32, 20));
  CHECK_THROWS_WITH(trace(alpha, {}, {{32, 32}}), Catch::Contains("has alpha"));
}

TEST_CASE("paper: a drawing with alpha traces and draws exactly as before") {
  const RgbaImage ring = test::drawShape(128, 128, test::subtract(test::disc(64, 64, 50), test::disc(64, 64, 20)));
  const auto outlines = trace(ring, {});
  REQUIRE(outlines.size() == 1);
  CHECK(outlines[0].holes.size() == 1);  // its transparent hole stays a hole
  CHECK_FALSE(tracedByColour(ring, {}));

  const std::string dir = test::scratchDirectory("paper-alpha");
  writePng(dir + "/ring.png", ring);
  writeRgbPng(dir + "/character.png", onPaper(128, 128, character));
  CHECK_FALSE(readPng(dir + "/character.png").hasAlpha);
  writeFileAtomically(dir + "/scene.json", R"({"version": 1, "keys": [
    {"name": "ring", "drawing": "ring.png"},
    {"name": "character", "drawing": "character.png", "holes": [[64, 76]]}]})");
  const Scene scene = loadScene(dir + "/scene.json");
  REQUIRE(scene.keys[1].holes.size() == 1);
  const std::vector<RgbaImage> drawings = readKeyDrawings(scene);
  CHECK(drawings[0].pixels == readPng(dir + "/ring.png").pixels);  // unchanged
  CHECK(drawings[1].hasAlpha);
  CHECK(drawings[1].at(3, 3)[3] == 0);
  CHECK(drawings[1].at(64, 76)[3] == 0);   // the marked belly
  CHECK(drawings[1].at(52, 44)[3] == 255);  // the eye
}

TEST_CASE("paper: the scene's holes fields are read and checked") {
  const std::string base = R"({"version": 1, "keys": [{"name": "a", "drawing": "a.png"REST}]TRACING})";
  auto scene = [&](const std::string& rest, const std::string& tracing) {
    std::string text = base;
    text.replace(text.find("REST"), 4, rest);
    text.replace(text.find("TRACING"), 7, tracing);
    return parseScene(text, "s.json");
  };
  CHECK(scene("", "").tracing.holes == PaperHoles::kMarked);
  CHECK(scene("", R"(, "tracing": {"holes": "enclosed-paper"})").tracing.holes == PaperHoles::kEnclosedPaper);
  CHECK(scene(R"(, "holes": [[1, 2], [3.5, 4]])", "").keys[0].holes.size() == 2);
  CHECK_THROWS_WITH(scene("", R"(, "tracing": {"holes": "all"})"),
                    Catch::Contains("s.json: tracing: holes: \"all\" is not \"marked\""));
  CHECK_THROWS_WITH(scene(R"(, "holes": [1, 2])", ""), Catch::Contains("key \"a\": holes: point 1"));
  CHECK_THROWS_WITH(scene(R"(, "holes": {"x": 1})", ""), Catch::Contains("key \"a\": holes: must be an array"));
}

TEST_CASE("paper: a scene on paper builds a multimesh with the marked hole and no other") {
  const std::string dir = test::scratchDirectory("paper-build");
  writePng(dir + "/character.png", onPaper(128, 128, character));  // RGBA, opaque everywhere: on paper too
  CHECK(readPng(dir + "/character.png").hasAlpha);
  writeFileAtomically(dir + "/scene.json", R"({"version": 1, "edge_length": 8, "keys": [
    {"name": "a", "drawing": "character.png"},
    {"name": "b", "drawing": "character.png"}]})");
  const BuiltScene plain = buildMultimesh(loadScene(dir + "/scene.json"), {});
  REQUIRE(plain.outlines[0].size() == 1);
  CHECK(plain.outlines[0][0].holes.empty());
  writeFileAtomically(dir + "/scene.json", R"({"version": 1, "edge_length": 8, "keys": [
    {"name": "a", "drawing": "character.png", "holes": [[64, 76]]},
    {"name": "b", "drawing": "character.png", "holes": [[64, 76]]}]})");
  const BuiltScene holed = buildMultimesh(loadScene(dir + "/scene.json"), {});
  CHECK(holed.outlines[0][0].holes.size() == 1);
  writeFileAtomically(dir + "/scene.json", R"({"version": 1, "keys": [
    {"name": "a", "drawing": "character.png", "holes": [[64, 30]]}, {"name": "b", "drawing": "character.png"}]})");
  CHECK_THROWS_WITH(buildMultimesh(loadScene(dir + "/scene.json"), {}),
                    Catch::Contains("scene.json: key \"a\": drawing ") && Catch::Contains("holes: point 1 [64, 30]"));
}

TEST_CASE("paper: a line too thin to have solid ink becomes partly transparent black (colour-to-alpha)") {
  // A dark ring 1.5 px wide round a white disc, on white paper: every pixel of the line is within
  // 2 px of the paper, so none is solid.
  auto ring = [](double x, double y) {
    const double r = std::hypot(x - 32, y - 32);
    return r > 20 && r < 21.5 ? Rgb{0, 0, 0} : kPaper;
  };
  const RgbaImage drawing = onPaper(64, 64, ring);
  const RgbaImage art = artwork(drawing, {});
  CHECK(art.at(32, 32)[3] == 255);  // the white disc inside is enclosed paper: kept
  CHECK(art.at(2, 2)[3] == 0);
  int partly = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const uint8_t* p = art.at(x, y);
      const double r = std::hypot(x + 0.5 - 32, y + 0.5 - 32);
      if (r < 21.5 || p[3] == 0) continue;  // the line's outer side, towards the paper
      CHECK(p[0] <= 2);                    // black ink, not grey
      CHECK(std::abs(p[3] - (255 - drawing.at(x, y)[0])) <= 1);  // alpha: the ink's share
      ++partly;
    }
  CHECK(partly > 50);
  // The line's inner side blends with the enclosed white, which stays: drawn as it is, opaque.
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double r = std::hypot(x + 0.5 - 32, y + 0.5 - 32);
      if (r < 20.3 && r > 18) CHECK(art.at(x, y)[3] == 255);
    }
}
