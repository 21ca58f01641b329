#include "meshing/mesh_svg.h"

#include <catch2/catch.hpp>

#include <array>
#include <regex>
#include <string>
#include <vector>

using namespace ib;

namespace {

// The text of an SVG element's content with the five XML entities undone.
std::string unescaped(std::string s) {
  const std::vector<std::pair<std::string, std::string>> entities = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [entity, c] : entities)
    for (size_t at = s.find(entity); at != std::string::npos; at = s.find(entity, at + c.size()))
      s.replace(at, entity.size(), c);
  return s;
}

double attribute(const std::string& element, const std::string& name) {
  std::smatch m;
  REQUIRE(std::regex_search(element, m, std::regex(" " + name + "=\"([-0-9.e+]+)\"")));
  return std::stod(m[1]);
}

// A 200 x 120 px drawing's mesh (two triangles over the whole drawing) whose one loop runs around
// the drawing's edge with features at all four corners, two of them collocated at the bottom left
// (their labels stack downwards) and some with names longer than the drawing is wide.
struct CornerScene {
  Multimesh mesh{4, {{0, 1, 2}, {0, 2, 3}}};
  KeyShape shape;
  int width = 200, height = 120;
  CornerScene() {
    Eigen::MatrixX2d x(4, 2);
    x << 0, 0, 200, 0, 200, 120, 0, 120;
    mesh.addKey(x, {}, {0, 1, 2, 3});
    ShapeLoop loop;
    loop.points = {{0, 0}, {100, 0}, {200, 0}, {200, 120}, {100, 120}, {0, 120}, {0, 120}};
    loop.features = {"top-left & <corner>", "", "top.right",
                     "bottom-right-corner-with-a-very-long-name-past-the-drawing", "", "bottom.left.MMMM",
                     "bottom.left.stacked.WWWW"};
    shape.loops = {loop};
  }
};

}  // namespace

TEST_CASE("mesh svg: every feature label's estimated box lies within the viewBox, at the drawing's corners too") {
  const CornerScene scene;
  const std::string svg = meshSvg(scene.mesh, 0, scene.shape, "not a png", scene.width, scene.height);
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("viewBox=\"([-0-9.]+) ([-0-9.]+) ([-0-9.]+) ([-0-9.]+)\"")));
  const double vx = std::stod(m[1]), vy = std::stod(m[2]), vw = std::stod(m[3]), vh = std::stod(m[4]);
  INFO("viewBox " << vx << ' ' << vy << ' ' << vw << ' ' << vh);
  // The drawing keeps its place and size, at one user unit a pixel, shown at a whole multiple.
  CHECK(vx <= 0);
  CHECK(vy <= 0);
  CHECK(vx + vw >= scene.width);
  CHECK(vy + vh >= scene.height);
  REQUIRE(std::regex_search(svg, m, std::regex("<svg [^>]* width=\"([0-9.]+)\" height=\"([0-9.]+)\"")));
  CHECK(std::stod(m[1]) == 4 * vw);  // 200 x 120 shown at 4x: 800 px wide, at least kShownPixels
  CHECK(std::stod(m[2]) == 4 * vh);
  CHECK(svg.find("<image width=\"200\" height=\"120\" opacity=\"0.6\" style=\"image-rendering:pixelated\"") != std::string::npos);

  const std::regex text("<text ([^>]*)>([^<]*)</text>");
  int labels = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator(); ++it, ++labels) {
    const std::string element = " " + (*it)[1].str(), content = unescaped((*it)[2]);
    const bool anchorEnd = element.find("text-anchor=\"end\"") != std::string::npos;
    const TextBox box = estimatedTextBox(content, attribute(element, "x"), attribute(element, "y"),
                                         attribute(element, "font-size"), anchorEnd);
    INFO("label \"" << content << "\": x " << box.x0 << ".." << box.x1 << ", y " << box.y0 << ".." << box.y1);
    CHECK(box.x0 >= vx);
    CHECK(box.y0 >= vy);
    CHECK(box.x1 <= vx + vw);
    CHECK(box.y1 <= vy + vh);
  }
  CHECK(labels == 5);
  // The width estimate leans wide: a narrow name takes less room than one of wide letters.
  const TextBox narrow = estimatedTextBox("iiii", 0, 0, 10, false), wide = estimatedTextBox("MMMM", 0, 0, 10, true);
  CHECK(narrow.x1 - narrow.x0 == Approx(16));
  CHECK(wide.x1 - wide.x0 == Approx(40));
  CHECK(wide.x1 == 0);
}

TEST_CASE("mesh svg: interior features are labelled dots, those with a radius inside a dashed circle of that radius") {
  const CornerScene scene;
  const std::string svg = meshSvg(scene.mesh, 0, scene.shape, "not a png", scene.width, scene.height,
                                  {{"eye", {60, 50}, 12}, {"belly", {150, 80}, 0}});
  CHECK(svg.find(">eye</text>") != std::string::npos);
  CHECK(svg.find(">belly</text>") != std::string::npos);
  const std::regex dashed("<circle cx=\"([-0-9.]+)\" cy=\"([-0-9.]+)\" r=\"([-0-9.]+)\" fill=\"none\"[^>]*stroke-dasharray");
  std::vector<std::array<double, 3>> circles;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), dashed); it != std::sregex_iterator(); ++it)
    circles.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3])});
  REQUIRE(circles.size() == 1);  // the belly has no radius
  CHECK(circles[0][0] == 60);
  CHECK(circles[0][1] == 50);
  CHECK(circles[0][2] == 12);
}

TEST_CASE("mesh svg: a sprite is shown at a whole multiple of its size, its larger side at least 768 px, and large "
          "drawings at their own size") {
  CHECK(svgScale(100, 96) == 8);
  CHECK(svgScale(16, 16) == 16);  // at most 16x
  CHECK(svgScale(768, 100) == 1);
  CHECK(svgScale(2048, 1536) == 1);
  CHECK(svgScale(300, 500) == 2);
  for (int side = 8; side <= 1024; side += 7) CHECK((svgScale(side, side) * side >= kShownPixels || svgScale(side, side) == 16));
}
