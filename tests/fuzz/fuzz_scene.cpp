// libFuzzer target: scene.json text through the scene parser (parseScene), which checks every
// field. Bad input must come back as InputError; anything else (another exception, a crash, a
// sanitizer finding) is a bug. Seeds: every bundled scene (scripts/fuzz.sh).
#include "core/error.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    ib::parseScene(text, "/nonexistent/fuzz/scene.json");
  } catch (const ib::InputError&) {
  }
  return 0;
}
