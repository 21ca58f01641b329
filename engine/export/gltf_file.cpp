#include "export/gltf_file.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace ib::gltf {

namespace {

namespace fs = std::filesystem;

// A tinygltf value as JSON (for the parts tinygltf 2.7 does not serialize: bufferView extensions).
nlohmann::json toJson(const tinygltf::Value& v) {
  switch (v.Type()) {
    case tinygltf::BOOL_TYPE: return v.Get<bool>();
    case tinygltf::INT_TYPE: return v.Get<int>();
    case tinygltf::REAL_TYPE: return v.Get<double>();
    case tinygltf::STRING_TYPE: return v.Get<std::string>();
    case tinygltf::ARRAY_TYPE: {
      nlohmann::json out = nlohmann::json::array();
      for (size_t i = 0; i < v.ArrayLen(); ++i) out.push_back(toJson(v.Get(static_cast<int>(i))));
      return out;
    }
    case tinygltf::OBJECT_TYPE: {
      nlohmann::json out = nlohmann::json::object();
      for (const std::string& key : v.Keys()) out[key] = toJson(v.Get(key));
      return out;
    }
    default: return nullptr;
  }
}

// The document's JSON: tinygltf's serialization of everything but the buffers, with the buffers
// added, the bufferViews' extensions (which tinygltf 2.7 drops) put back, and channels that
// target a pointer rather than a node left without "node".
std::string documentJson(const GltfDocument& doc, const std::string& binUri) {
  tinygltf::TinyGLTF writer;
  std::ostringstream stream;
  if (!writer.WriteGltfSceneToStream(&doc.model, stream, false, false))
    throw std::runtime_error("glTF export: tinygltf could not serialize the document");
  nlohmann::json json = nlohmann::json::parse(stream.str());
  nlohmann::json buffers = nlohmann::json::array();
  nlohmann::json main = {{"byteLength", doc.bin.size()}};
  if (!binUri.empty()) main["uri"] = binUri;
  buffers.push_back(main);
  if (doc.fallbackBytes)
    buffers.push_back({{"byteLength", doc.fallbackBytes}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  json["buffers"] = buffers;
  for (size_t i = 0; i < doc.model.bufferViews.size(); ++i)
    for (const auto& [name, value] : doc.model.bufferViews[i].extensions) json["bufferViews"][i]["extensions"][name] = toJson(value);
  if (json.contains("animations"))
    for (nlohmann::json& animation : json["animations"])
      for (nlohmann::json& channel : animation["channels"])
        if (channel["target"].value("node", 0) < 0) channel["target"].erase("node");
  return json.dump();
}

// A file name as a relative URI reference: RFC 3986's unreserved characters as they are, every
// other byte percent-encoded (a space becomes %20).
std::string uriOf(const std::string& name) {
  std::string out;
  for (unsigned char c : name) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
      out.push_back(static_cast<char>(c));
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

void appendU32(std::string& out, uint32_t v) {
  for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
}

std::string glbBytes(const GltfDocument& doc) {
  std::string json = documentJson(doc, "");
  while (json.size() % 4) json.push_back(' ');
  std::string bin(doc.bin.begin(), doc.bin.end());
  while (bin.size() % 4) bin.push_back('\0');
  const uint64_t total = 12 + 8 + json.size() + 8 + bin.size();
  if (total > 0xFFFFFFFFull)
    throw InputError("the .glb would be " + std::to_string(total >> 20) +
                     " MiB, more than the format's 4 GiB: export fewer frames (--frames), drop frames (--max-error) or compress (--meshopt)");
  std::string out;
  appendU32(out, 0x46546C67);  // "glTF"
  appendU32(out, 2);
  appendU32(out, static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  appendU32(out, static_cast<uint32_t>(json.size()));
  appendU32(out, 0x4E4F534A);  // "JSON"
  out += json;
  appendU32(out, static_cast<uint32_t>(bin.size()));
  appendU32(out, 0x004E4942);  // "BIN\0"
  out += bin;
  return out;
}

}  // namespace

Container containerOf(const std::string& path, const std::string& field) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".glb") return Container::kGlb;
  if (ext == ".gltf") return Container::kGltf;
  throw InputError(field + " " + inQuotes(path) + ": name the file .glb (binary glTF) or .gltf (JSON with a .bin beside it)");
}

size_t documentBytes(const GltfDocument& doc, Container container, const std::string& binName) {
  if (container == Container::kGlb) return glbBytes(doc).size();
  return documentJson(doc, uriOf(binName)).size() + doc.bin.size();
}

size_t writeDocument(const GltfDocument& doc, const std::string& path) {
  if (containerOf(path, "-o") == Container::kGlb) {
    const std::string bytes = glbBytes(doc);
    writeFileAtomically(path, bytes);
    return bytes.size();
  }
  const fs::path gltf(path);
  const fs::path bin = fs::path(gltf).replace_extension(".bin");
  const bool hadBin = fs::exists(bin);
  writeFileAtomically(bin.string(), std::string(doc.bin.begin(), doc.bin.end()));
  try {
    const std::string json = documentJson(doc, uriOf(bin.filename().string()));
    writeFileAtomically(path, json);
    return json.size() + doc.bin.size();
  } catch (...) {
    std::error_code ignored;
    if (!hadBin) fs::remove(bin, ignored);
    throw;
  }
}

}  // namespace ib::gltf
