// Versioned binary file for a Multimesh, so later stages can cache it.
//
// Layout (little-endian): magic "IBMMESH\0", u32 version, u32 n, u32 t, u32 m,
// t x 3 u32 triangles, t f64 kappa, then per key: n x 2 f64 positions, u32 pair count,
// 4 u32 per cohesive pair, u32 boundary count, u32 per boundary vertex; last a u64 FNV-1a
// checksum of every byte before it. Loading checks sizes, version and checksum, then
// Multimesh::validate(), so a truncated, corrupt or wrong-version file is an InputError.
#pragma once

#include "multimesh/multimesh.h"

#include <string>

namespace ib {

constexpr unsigned kMultimeshFileVersion = 1;

std::string encodeMultimesh(const Multimesh& mesh);
// `source` names the data in error messages (usually the file path).
Multimesh decodeMultimesh(const std::string& bytes, const std::string& source);

void saveMultimesh(const Multimesh& mesh, const std::string& path);  // atomic
Multimesh loadMultimesh(const std::string& path);

}  // namespace ib
