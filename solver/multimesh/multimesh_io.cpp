#include "multimesh/multimesh_io.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <cstdint>
#include <cstring>

namespace ib {

namespace {

constexpr char kMagic[8] = {'I', 'B', 'M', 'M', 'E', 'S', 'H', '\0'};

uint64_t fnv1a(const char* data, size_t size) {
  uint64_t h = 1469598103934665603ull;
  for (size_t i = 0; i < size; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 1099511628211ull;
  }
  return h;
}

class Writer {
 public:
  template <class T>
  void put(T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes.append(raw, sizeof(T));
  }
  std::string bytes;
};

class Reader {
 public:
  Reader(const std::string& bytes, size_t end, const std::string& source) : bytes_(bytes), end_(end), source_(source) {}
  template <class T>
  T get(const char* what) {
    if (pos_ + sizeof(T) > end_) throw InputError(source_ + ": truncated while reading " + what);
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  // Guards an allocation of count items of itemSize bytes against the bytes left.
  void expect(uint64_t count, size_t itemSize, const char* what) const {
    if (count > (end_ - pos_) / itemSize) throw InputError(source_ + ": truncated or corrupt " + what + " count");
  }
  size_t position() const { return pos_; }

 private:
  const std::string& bytes_;
  size_t end_;
  const std::string& source_;
  size_t pos_ = 0;
};

}  // namespace

std::string encodeMultimesh(const Multimesh& mesh) {
  Writer w;
  w.bytes.append(kMagic, sizeof(kMagic));
  w.put<uint32_t>(kMultimeshFileVersion);
  w.put<uint32_t>(mesh.vertexCount());
  w.put<uint32_t>(mesh.triangleCount());
  w.put<uint32_t>(mesh.keyCount());
  for (const Triangle& tri : mesh.triangles())
    for (int v : tri) w.put<uint32_t>(v);
  for (int t = 0; t < mesh.triangleCount(); ++t) w.put<double>(mesh.stiffness(t));
  for (int k = 0; k < mesh.keyCount(); ++k) {
    const Eigen::MatrixX2d X = mesh.keyPositions(k);
    for (int v = 0; v < mesh.vertexCount(); ++v) {
      w.put<double>(X(v, 0));
      w.put<double>(X(v, 1));
    }
    w.put<uint32_t>(mesh.cohesivePairs(k).size());
    for (const CohesivePair& p : mesh.cohesivePairs(k))
      for (int v : {p.a, p.b, p.c, p.d}) w.put<uint32_t>(v);
    w.put<uint32_t>(mesh.boundaryVertices(k).size());
    for (int v : mesh.boundaryVertices(k)) w.put<uint32_t>(v);
  }
  w.put<uint64_t>(fnv1a(w.bytes.data(), w.bytes.size()));
  return w.bytes;
}

namespace {

Multimesh decodeUnprefixed(const std::string& bytes, const std::string& source) {
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    throw InputError(source + ": not an inbetween multimesh file");
  if (bytes.size() < sizeof(kMagic) + 4 + 8) throw InputError(source + ": truncated header");
  uint32_t version;
  std::memcpy(&version, bytes.data() + sizeof(kMagic), 4);
  if (version != kMultimeshFileVersion)
    throw InputError(source + ": multimesh file version " + std::to_string(version) + ", this build reads version " +
                     std::to_string(kMultimeshFileVersion) + " (rebuild it with `inbetween mesh`)");
  const size_t body = bytes.size() - 8;
  uint64_t stored;
  std::memcpy(&stored, bytes.data() + body, 8);
  if (stored != fnv1a(bytes.data(), body)) throw InputError(source + ": checksum mismatch (file is corrupt or truncated)");

  Reader r(bytes, body, source);
  for (size_t i = 0; i < sizeof(kMagic) + 4; ++i) r.get<char>("header");
  const uint32_t n = r.get<uint32_t>("vertex count");
  const uint32_t t = r.get<uint32_t>("triangle count");
  const uint32_t m = r.get<uint32_t>("key count");
  // Checked before anything is allocated: with m = 0 the key positions would not bound n by the
  // file's size, and a corrupt n would build a mesh of billions of vertices.
  if (m == 0) throw InputError(source + ": multimesh has no keys (key count 0; rebuild it with `inbetween mesh`)");
  r.expect(static_cast<uint64_t>(n) * m, 16, "key position");
  r.expect(t, 3 * 4 + 8, "triangle");
  std::vector<Triangle> tris(t);
  for (auto& tri : tris)
    for (int& v : tri) v = static_cast<int>(r.get<uint32_t>("triangles"));
  std::vector<double> kappa(t);
  for (double& k : kappa) k = r.get<double>("stiffness");
  r.expect(static_cast<uint64_t>(n) * m, 16, "key position");
  Multimesh mesh(static_cast<int>(n), tris);
  for (uint32_t i = 0; i < t; ++i) mesh.setStiffness(static_cast<int>(i), kappa[i]);
  for (uint32_t k = 0; k < m; ++k) {
    Eigen::MatrixX2d X(n, 2);
    for (uint32_t v = 0; v < n; ++v) {
      X(v, 0) = r.get<double>("positions");
      X(v, 1) = r.get<double>("positions");
    }
    const uint32_t pairCount = r.get<uint32_t>("cohesive pair count");
    r.expect(pairCount, 16, "cohesive pair");
    std::vector<CohesivePair> pairs(pairCount);
    for (auto& p : pairs) {
      p.a = static_cast<int>(r.get<uint32_t>("cohesive pairs"));
      p.b = static_cast<int>(r.get<uint32_t>("cohesive pairs"));
      p.c = static_cast<int>(r.get<uint32_t>("cohesive pairs"));
      p.d = static_cast<int>(r.get<uint32_t>("cohesive pairs"));
    }
    const uint32_t boundaryCount = r.get<uint32_t>("boundary count");
    r.expect(boundaryCount, 4, "boundary vertex");
    std::vector<int> boundary(boundaryCount);
    for (int& v : boundary) v = static_cast<int>(r.get<uint32_t>("boundary vertices"));
    mesh.addKey(X, std::move(pairs), std::move(boundary));
  }
  if (r.position() != body) throw InputError(source + ": unexpected bytes after the last key");
  mesh.validate();
  return mesh;
}

}  // namespace

Multimesh decodeMultimesh(const std::string& bytes, const std::string& source) {
  try {
    return decodeUnprefixed(bytes, source);
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.rfind(source + ":", 0) == 0) throw;
    throw InputError(source + ": " + message);
  }
}

void saveMultimesh(const Multimesh& mesh, const std::string& path) { writeFileAtomically(path, encodeMultimesh(mesh)); }

Multimesh loadMultimesh(const std::string& path) { return decodeMultimesh(readFile(path), path); }

}  // namespace ib
