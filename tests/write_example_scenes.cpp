// Writes the example scenes (and, with --bad, the bad ones) into a folder:
// write_example_scenes FOLDER [--bad]. Used for assets/; the command-line tests write them
// themselves (tests/cli_support.h).
#include "testkit/example_scenes.h"

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fputs("usage: write_example_scenes FOLDER [--bad]\n", stderr);
    return 2;
  }
  try {
    for (const auto& scene : test::goodScenes()) test::writeScene(scene, argv[1]);
    for (const auto& scene : test::comeshScenes()) test::writeScene(scene, argv[1]);
    test::writeScene(test::starSequence(), argv[1]);
    if (argc > 2 && std::string(argv[2]) == "--bad") test::writeBadScenes(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_example_scenes: %s\n", e.what());
    return 1;
  }
  return 0;
}
