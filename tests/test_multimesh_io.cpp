#include "core/atomic_file.h"
#include "core/error.h"
#include "multimesh/multimesh_io.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <random>

using namespace ib;

namespace {

void requireSame(const Multimesh& a, const Multimesh& b) {
  REQUIRE(a.vertexCount() == b.vertexCount());
  REQUIRE(a.triangles() == b.triangles());
  REQUIRE(a.keyCount() == b.keyCount());
  REQUIRE((a.stiffnesses() - b.stiffnesses()).norm() == 0.0);
  for (int k = 0; k < a.keyCount(); ++k) {
    REQUIRE((a.keyPositions(k) - b.keyPositions(k)).norm() == 0.0);
    REQUIRE(a.boundaryVertices(k) == b.boundaryVertices(k));
    REQUIRE(a.cohesivePairs(k).size() == b.cohesivePairs(k).size());
    for (size_t j = 0; j < a.cohesivePairs(k).size(); ++j) {
      const auto &p = a.cohesivePairs(k)[j], &q = b.cohesivePairs(k)[j];
      REQUIRE((p.a == q.a && p.b == q.b && p.c == q.c && p.d == q.d));
    }
  }
}

std::string tempPath(const std::string& name) { return "inbetween_test_" + name; }

}  // namespace

TEST_CASE("multimesh file: every fixture round-trips exactly through a file") {
  for (auto& f : test::allFixtures()) {
    INFO(f.name);
    f.mesh.setStiffness(0, 3.25);
    const std::string path = tempPath("roundtrip.ibmesh");
    saveMultimesh(f.mesh, path);
    requireSame(f.mesh, loadMultimesh(path));
    std::remove(path.c_str());
  }
}

TEST_CASE("multimesh file: every truncation is an input error naming the source") {
  const auto f = test::gluedSquares(4, 1.0, 0.2);
  const std::string bytes = encodeMultimesh(f.mesh);
  for (size_t cut = 0; cut < bytes.size(); cut += 1 + cut / 7) {
    INFO("truncated to " << cut << " of " << bytes.size() << " bytes");
    REQUIRE_THROWS_WITH(decodeMultimesh(bytes.substr(0, cut), "cut.ibmesh"), Catch::StartsWith("cut.ibmesh: "));
  }
}

TEST_CASE("multimesh file: flipped bytes are caught (fixed seed)") {
  const auto f = test::gluedSquares(4, 1.0, 0.2);
  const std::string bytes = encodeMultimesh(f.mesh);
  std::mt19937 rng(1234);
  for (int trial = 0; trial < 200; ++trial) {
    std::string corrupt = bytes;
    const size_t at = rng() % corrupt.size();
    corrupt[at] = static_cast<char>(corrupt[at] ^ (1 + rng() % 255));
    INFO("byte " << at);
    REQUIRE_THROWS_AS(decodeMultimesh(corrupt, "corrupt.ibmesh"), InputError);
  }
}

TEST_CASE("multimesh file: a wrong version says which versions are involved") {
  const auto f = test::strip(100, 2);
  std::string bytes = encodeMultimesh(f.mesh);
  bytes[8] = 99;  // version field follows the 8-byte magic
  REQUIRE_THROWS_WITH(decodeMultimesh(bytes, "old.ibmesh"), Catch::Contains("version 99") && Catch::Contains("version 1"));
}

TEST_CASE("multimesh file: missing and foreign files are input errors naming the path") {
  REQUIRE_THROWS_WITH(loadMultimesh("no/such/dir/mesh.ibmesh"), Catch::StartsWith("no/such/dir/mesh.ibmesh: "));
  const std::string path = tempPath("foreign.ibmesh");
  writeFileAtomically(path, "PNG? no, just text");
  REQUIRE_THROWS_WITH(loadMultimesh(path), Catch::Contains("not an inbetween multimesh file"));
  std::remove(path.c_str());
}

TEST_CASE("atomic write: a failed write leaves the previous file intact") {
  const std::string path = tempPath("atomic.txt");
  writeFileAtomically(path, "good");
  REQUIRE_THROWS_AS(writeFileAtomically("no/such/dir/file", "bad"), InputError);
  REQUIRE(readFile(path) == "good");
  std::remove(path.c_str());
}
