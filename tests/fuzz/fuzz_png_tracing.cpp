// libFuzzer target: PNG bytes through the decoder and, for images up to 256 x 256, the tracing
// path (shape mask and outlines). Bad input must come back as InputError. Seeds: the bundled
// drawings, scaled down (scripts/fuzz.sh).
#include "core/error.h"
#include "core/png_image.h"
#include "meshing/tracing.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    const ib::RgbaImage image = ib::decodePng(bytes, "fuzz.png");
    if (static_cast<long>(image.width) * image.height > 256 * 256) return 0;
    const ib::TracingOptions options;
    const ib::ShapeMask mask = ib::shapeMask(image, options);
    (void)ib::traceOutlines(mask, options, "fuzz.png");
  } catch (const ib::InputError&) {
  }
  return 0;
}
