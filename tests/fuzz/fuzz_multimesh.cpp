// libFuzzer target: multimesh file bytes through decodeMultimesh (sizes, version, checksum,
// topology and Multimesh::validate). A random input almost never carries a right checksum, so
// when the first byte is odd the target first writes the right one over the last 8 bytes: the
// structure behind the checksum gets fuzzed too. Bad input must come back as InputError.
// Seeds: the bundled scenes' multimeshes (scripts/fuzz.sh).
#include "core/error.h"
#include "multimesh/multimesh_io.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace {

// FNV-1a, 64 bit, as the file format's checksum (multimesh_io.h).
uint64_t fnv1a(const char* bytes, size_t size) {
  uint64_t hash = 1469598103934665603ull;
  for (size_t i = 0; i < size; ++i) hash = (hash ^ static_cast<unsigned char>(bytes[i])) * 1099511628211ull;
  return hash;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  if ((data[0] & 1) && bytes.size() >= 8) {
    const uint64_t sum = fnv1a(bytes.data(), bytes.size() - 8);
    std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);  // little-endian, as the format
  }
  try {
    (void)ib::decodeMultimesh(bytes, "fuzz.ibmesh");
  } catch (const ib::InputError&) {
  }
  return 0;
}
