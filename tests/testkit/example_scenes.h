// Example scenes generated in code, with their drawings: the geometric cases (square to
// arch stretched and notched, disc to ring, one cell to two, nested rings) and bad scenes, one
// per kind of mistake. Tests write them to scratch folders; `write_example_scenes` writes them to
// a folder (the bundled assets/ and the command-line tests come from it).
#pragma once

#include "core/png_image.h"

#include <string>
#include <utility>
#include <vector>

namespace test {

struct ExampleScene {
  std::string name;                                          // folder name
  std::string json;                                          // scene.json text
  std::vector<std::pair<std::string, ib::RgbaImage>> drawings;  // file name, image
};

// The scenes that must build.
std::vector<ExampleScene> goodScenes();

// Comesh Optimization cases (paper Figures 4, 10, 18): pentagon to star, thin-spoked stars with
// five and six tips, square to hexagon. Features pin the polygon's corners to the star's tips.
std::vector<ExampleScene> comeshScenes();

// Three keys: pentagon, star and a thinner star, for the order of keys in the cyclic MIPS sum.
ExampleScene threeStars();

// Sixteen keys, a pentagon sharpening step by step into a thin star: the many-key benchmark.
ExampleScene starSequence();

// Writes FOLDER/NAME/scene.json and its drawings.
void writeScene(const ExampleScene& scene, const std::string& folder);

// The scene files of the bundled assets (FOLDER/NAME/scene.json), sorted by NAME.
std::vector<std::string> bundledSceneFiles(const std::string& folder);

// Bad scene files under FOLDER/bad/, each named after its mistake (missing-drawing.json, ...),
// drawing on FOLDER/square-arch-notch/: returns (file, part of the expected message) pairs. Two
// are odd but build, with a note: canvas-sizes.json (keys on canvases of different sizes) and
// one-key.json.
std::vector<std::pair<std::string, std::string>> writeBadScenes(const std::string& folder);

}  // namespace test
