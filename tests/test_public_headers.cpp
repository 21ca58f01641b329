// The front ends' headers are thin: including the frame stream, the interpolator and the
// multimesh brings in Eigen's dense core and the standard library, but none of OpenMesh, OpenMP,
// the sparse factorization or nlohmann. These headers come first in this file, so each guard
// below tells what they pulled in; a violation fails the build. Every other header apps/ and
// engine/ include is compiled alone with the same guards (tests/CMakeLists.txt).
#include "animation/frame_stream.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"

#if defined(OPENMESH_CONFIG_H) || defined(OPENMESH_TRIMESH_ARRAY_KERNEL_HH)
#error "a public header includes OpenMesh"
#endif
#if defined(_OMP_H)
#error "a public header includes omp.h"
#endif
#if defined(EIGEN_SPARSECORE_MODULE_H) || defined(EIGEN_SPARSE_MODULE_H)
#error "a public header includes Eigen's sparse modules (the factorization)"
#endif
#if defined(INCLUDE_NLOHMANN_JSON_HPP_)
#error "a public header includes nlohmann/json"
#endif

#include <catch2/catch.hpp>

TEST_CASE("public API: Interpolator and FrameStream hold only a pointer to their state") {
  CHECK(sizeof(ib::Interpolator) == sizeof(void*));
  CHECK(sizeof(ib::FrameStream) == sizeof(void*));
}

TEST_CASE("public API: every header apps/ and engine/ include compiles alone without OpenMesh, OpenMP, the factorization or nlohmann") {
  // The headers are compiled by the build (tests/CMakeLists.txt, inbetween_public_headers): a
  // violation fails it. Here: the scan of apps/ and engine/ found them.
  CHECK(INBETWEEN_PUBLIC_HEADERS >= 30);
}
