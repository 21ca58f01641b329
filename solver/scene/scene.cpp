#include "scene/scene.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_fields.h"
#include "core/suggest.h"
#include "scene/parameter_json.h"
#include "scene/scene_animation.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <set>
#include <sstream>

namespace ib {

using nlohmann::json;

namespace {

using namespace json_fields;

CutKind cutKind(const json& cut, const Context& at) {
  const std::string kind = text(cut, "kind", at);
  if (kind == "notch") return CutKind::kNotch;
  if (kind == "split") return CutKind::kSplit;
  if (kind == "slit") return CutKind::kSlit;
  throw at.in("kind").error(inQuotes(kind) + " is not a cut kind (notch, split or slit)");
}

CutSpec parseCut(const json& j, const Context& key, size_t index) {
  const Context first = element(j, key, "cut", index);
  requireObject(j, first, {"name", "kind", "points", "release", "release_window"});
  CutSpec cut;
  cut.name = text(j, "name", first);
  const Context at = key.in("cut " + inQuotes(cut.name));
  if (cut.name.find('.') != std::string::npos) throw at.error("a cut's name may not contain '.'");
  cut.kind = cutKind(j, at);
  if (!j.contains("points") || !j["points"].is_array() || j["points"].size() < 2)
    throw at.error("needs \"points\": at least 2 points [x, y]");
  for (size_t i = 0; i < j["points"].size(); ++i)
    cut.points.push_back(point(j["points"][i], at.in("point " + std::to_string(i + 1))));
  for (size_t i = 1; i < cut.points.size(); ++i)
    if ((cut.points[i] - cut.points[i - 1]).norm() < 1e-9)
      throw at.error("points " + std::to_string(i) + " and " + std::to_string(i + 1) + " coincide");
  if (j.contains("release")) cut.release = number(j, "release", 0.5, at, 0, 1);
  if (j.contains("release_window")) cut.releaseWindow = number(j, "release_window", 1, at, 0, 1, true);
  return cut;
}

KeySpec parseKey(const json& j, const Context& scene, const std::filesystem::path& folder, size_t index) {
  requireObject(j, element(j, scene, "key", index), {"name", "drawing", "features", "interior_features", "cuts", "holes"});
  KeySpec key;
  key.name = text(j, "name", element(j, scene, "key", index));
  const Context at = scene.in("key " + inQuotes(key.name));
  const std::filesystem::path drawing = text(j, "drawing", at);
  key.drawing = (drawing.is_absolute() ? drawing : folder / drawing).lexically_normal().string();
  if (j.contains("features")) {
    const json& features = j["features"];
    if (!features.is_object()) throw at.in("features").error("must be an object {\"name\": [x, y], ...}");
    for (auto it = features.begin(); it != features.end(); ++it) {
      if (it.key().empty()) throw at.in("features").error("a feature needs a non-empty name");
      key.features[it.key()] = point(it.value(), at.in("feature " + inQuotes(it.key())));
    }
  }
  if (j.contains("interior_features")) {
    const json& features = j["interior_features"];
    if (!features.is_object())
      throw at.in("interior_features").error("must be an object {\"name\": [x, y], ...}: points inside the shape");
    for (auto it = features.begin(); it != features.end(); ++it) {
      const Context f = at.in("interior feature " + inQuotes(it.key()));
      if (it.key().empty()) throw at.in("interior_features").error("an interior feature needs a non-empty name");
      if (it.key().find('.') != std::string::npos)
        throw f.error("names with a '.' are reserved for the features cuts create; rename it without the '.' in every key");
      if (it.value().is_object()) {  // {"at": [x, y], "radius": r}
        requireObject(it.value(), f, {"at", "radius"});
        if (!it.value().contains("at")) throw f.error("needs \"at\": [x, y], the point in drawing pixels");
        key.interiorFeatures[it.key()] = point(it.value()["at"], f.in("at"));
        if (it.value().contains("radius")) key.interiorRadii[it.key()] = number(it.value(), "radius", 0, f, kMinInteriorRadius, kMaxInteriorRadius);
      } else {
        key.interiorFeatures[it.key()] = point(it.value(), f, "in drawing pixels, or {\"at\": [x, y], \"radius\": r}");
      }
    }
  }
  if (j.contains("cuts")) {
    if (!j["cuts"].is_array()) throw at.in("cuts").error("must be an array of cuts");
    for (size_t c = 0; c < j["cuts"].size(); ++c) {
      key.cuts.push_back(parseCut(j["cuts"][c], at, c));
      for (size_t other = 0; other + 1 < key.cuts.size(); ++other)
        if (key.cuts[other].name == key.cuts.back().name)
          throw at.error("cut " + inQuotes(key.cuts.back().name) + " is drawn twice");
    }
  }
  if (j.contains("holes")) {
    if (!j["holes"].is_array()) throw at.in("holes").error("must be an array of points [x, y], one inside each hole");
    for (size_t i = 0; i < j["holes"].size(); ++i)
      key.holes.push_back(point(j["holes"][i], at.in("holes").in("point " + std::to_string(i + 1))));
  }
  return key;
}

// "key "a"", "keys "a" and "b"", "keys "a", "b" and "c"".
std::string keyList(const Scene& scene, const std::vector<int>& keys) {
  std::string list = keys.size() == 1 ? "key " : "keys ";
  for (size_t i = 0; i < keys.size(); ++i)
    list += (i == 0 ? "" : i + 1 == keys.size() ? " and " : ", ") + inQuotes(scene.keys[keys[i]].name);
  return list;
}

// Every key places the same names (`what`: "feature", "interior feature"; namesOf(key) lists a
// key's). A name that some keys place and others do not is blamed on the side that looks wrong,
// so a typo is named where it is: the keys missing a name most keys place ("does not place
// feature "top" (keys "rest" and "open" do); it places "tpo": did you mean "top"?"), or the keys
// placing a name few place ("places feature "tpo", which key "rest" does not (did you mean
// "top"?)"). On a tie the first key's names are taken as meant. `rule` ends the message.
void checkSameNames(const Scene& scene, const Context& at, const std::string& what,
                    const std::function<std::vector<std::string>(const KeySpec&)>& namesOf, const std::string& rule) {
  const int keys = static_cast<int>(scene.keys.size());
  std::map<std::string, std::vector<int>> placers;  // name -> the keys placing it, in order
  for (int k = 0; k < keys; ++k)
    for (const std::string& name : namesOf(scene.keys[k])) placers[name].push_back(k);
  std::vector<std::pair<std::string, std::vector<int>>> partial;
  for (const auto& entry : placers)
    if (static_cast<int>(entry.second.size()) < keys) partial.push_back(entry);
  std::stable_sort(partial.begin(), partial.end(), [](const auto& a, const auto& b) { return a.second.size() > b.second.size(); });
  for (const auto& [name, placing] : partial) {
    std::vector<int> missing;
    for (int k = 0; k < keys; ++k)
      if (std::find(placing.begin(), placing.end(), k) == placing.end()) missing.push_back(k);
    const int count = static_cast<int>(placing.size());
    const bool meant = 2 * count > keys || (2 * count == keys && placing.front() == 0);
    if (meant) {  // the keys missing it are wrong: perhaps they place a near name instead
      const KeySpec& key = scene.keys[missing.front()];
      std::string typo;
      for (const std::string& own : namesOf(key))
        if (static_cast<int>(placers[own].size()) < keys && !didYouMean(own, {name}).empty())
          typo = "; it places " + inQuotes(own) + ": did you mean " + inQuotes(name) + "?";
      throw at.in("key " + inQuotes(key.name)).error("does not place " + what + " " + inQuotes(name) + " (" +
                                                    keyList(scene, placing) + (count == 1 ? " does" : " do") + ")" + typo + rule);
    }
    // The keys placing it are wrong: a typo of a name the others place, or one too many.
    const KeySpec& key = scene.keys[placing.front()];
    std::vector<std::string> theirs;
    for (const std::string& other : namesOf(scene.keys[missing.front()])) theirs.push_back(other);
    const std::string suggestion = didYouMean(name, theirs);
    throw at.in("key " + inQuotes(key.name)).error("places " + what + " " + inQuotes(name) + ", which " + keyList(scene, missing) +
                                                  (missing.size() == 1 ? " does" : " do") + " not" +
                                                  (suggestion.empty() ? ": place it in every key, or in none" : suggestion) + rule);
  }
}

// A plain feature named with a '.', which is reserved for the features cuts create: what the cut
// named before the dot creates, or that there is no such cut, and what to rename it to.
InputError dottedFeature(const Context& key, const std::string& f,
                         const std::map<std::string, std::pair<CutKind, std::vector<int>>>& cuts) {
  std::string plain = f;
  std::replace(plain.begin(), plain.end(), '.', '-');
  const std::string cut = f.substr(0, f.find('.'));
  const auto it = cuts.find(cut);
  std::string what = "feature " + inQuotes(f) + ": names with a '.' are reserved for the features cuts create (" +
                     "CUT.left, CUT.right, CUT.tip for a notch named CUT; see docs/scene-format.md, \"Features and cuts\"), ";
  if (it == cuts.end())
    return key.error(what + "and this scene has no cut " + inQuotes(cut) + ": rename it to " + inQuotes(plain) +
                     " in every key that places it");
  std::string created;
  for (const std::string& name : cutFeatureNames(cut, it->second.first)) created += (created.empty() ? "" : ", ") + inQuotes(name);
  return key.error(what + "and cut " + inQuotes(cut) + " creates " + created + didYouMean(f, cutFeatureNames(cut, it->second.first)) +
                   ": use one of those, or if " + inQuotes(f) + " is a plain feature, rename it to " + inQuotes(plain) +
                   " in every key that places it");
}

// Every key places the same plain features; a cut's features are placed exactly by the keys where
// it is open; keys where it is closed draw it with the same kind.
void checkCorrespondence(const Scene& scene, const Context& at) {
  std::map<std::string, std::pair<CutKind, std::vector<int>>> cuts;  // name -> kind, keys closed
  std::vector<std::pair<int, const CutSpec*>> timings;               // every key's cuts
  for (int k = 0; k < static_cast<int>(scene.keys.size()); ++k)
    for (const CutSpec& c : scene.keys[k].cuts) {
      auto [it, fresh] = cuts.insert({c.name, {c.kind, {}}});
      if (!fresh && it->second.first != c.kind)
        throw at.in("cut " + inQuotes(c.name)).error("is a different kind in key " + inQuotes(scene.keys[k].name) +
                                                  " than in key " + inQuotes(scene.keys[it->second.second[0]].name));
      it->second.second.push_back(k);
      timings.push_back({k, &c});
    }
  // A cut's own timing: the keys that close it agree, or leave it out.
  for (size_t a = 0; a < timings.size(); ++a)
    for (size_t b = 0; b < a; ++b) {
      const CutSpec &x = *timings[a].second, &y = *timings[b].second;
      if (x.name != y.name) continue;
      const auto clash = [&](const std::optional<double>& p, const std::optional<double>& q, const std::string& field) {
        if (p && q && *p != *q)
          throw at.in("cut " + inQuotes(x.name)).error(field + " is " + std::to_string(*p) + " in key " +
                                                    inQuotes(scene.keys[timings[a].first].name) + " and " + std::to_string(*q) +
                                                    " in key " + inQuotes(scene.keys[timings[b].first].name) +
                                                    ": give one value (in one key is enough)");
      };
      clash(x.release, y.release, "\"release\"");
      clash(x.releaseWindow, y.releaseWindow, "\"release_window\"");
    }
  std::map<std::string, std::string> cutOfFeature;
  for (const auto& [name, cut] : cuts) {
    if (cut.second.size() == scene.keys.size())
      throw at.in("cut " + inQuotes(name)).error("is closed in every key; a cut must open in at least one key");
    for (const std::string& f : cutFeatureNames(name, cut.first)) cutOfFeature[f] = name;
  }
  // Plain features: the union over keys must be placed everywhere.
  std::map<std::string, std::string> plain;  // feature -> a key placing it
  for (const KeySpec& key : scene.keys)
    for (const auto& [f, p] : key.features) {
      if (cutOfFeature.count(f)) continue;
      const size_t dot = f.find('.');
      if (dot != std::string::npos) throw dottedFeature(at.in("key " + inQuotes(key.name)), f, cuts);
      plain.insert({f, key.name});
    }
  checkSameNames(scene, at, "feature",
                 [&](const KeySpec& key) {
                   std::vector<std::string> names;
                   for (const auto& [f, p] : key.features)
                     if (plain.count(f)) names.push_back(f);
                   return names;
                 },
                 "");
  for (const auto& [name, cut] : cuts)
    for (int k = 0; k < static_cast<int>(scene.keys.size()); ++k) {
      const bool closed = std::count(cut.second.begin(), cut.second.end(), k) > 0;
      for (const std::string& f : cutFeatureNames(name, cut.first)) {
        const bool placed = scene.keys[k].features.count(f) > 0;
        if (closed && placed)
          throw at.in("cut " + inQuotes(name)).error("key " + inQuotes(scene.keys[k].name) + " draws the cut, so it may not place feature " +
                                                  inQuotes(f) + " (the cut creates it)");
        if (!closed && !placed)
          throw at.in("cut " + inQuotes(name)).error("key " + inQuotes(scene.keys[k].name) + " does not place feature " + inQuotes(f));
      }
    }
}

// Every key places the same interior features, none named like a plain feature. Where they lie
// against each key's shape is checked once it is traced (meshing/key_shape.h, checkInteriorFeatures).
void checkInteriorFeatures(const Scene& scene, const Context& at) {
  for (const KeySpec& key : scene.keys)
    for (const auto& [f, p] : key.interiorFeatures) {
      for (const KeySpec& other : scene.keys)
        if (other.features.count(f))
          throw at.in("key " + inQuotes(key.name)).error("interior feature " + inQuotes(f) + " has the name of a feature key " +
                                                      inQuotes(other.name) + " places on its outline; give it another name");
    }
  checkSameNames(scene, at, "interior feature",
                 [](const KeySpec& key) {
                   std::vector<std::string> names;
                   for (const auto& [f, p] : key.interiorFeatures) names.push_back(f);
                   return names;
                 },
                 ": every key places the same interior features, each where that point of the drawing is in this key");
}

std::string shortNumber(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// An interior feature's radius, given in one key or several (the same), holds in every key.
void shareInteriorRadii(Scene& scene, const Context& at) {
  std::map<std::string, std::pair<double, std::string>> radius;  // feature -> radius, the key giving it
  for (const KeySpec& key : scene.keys)
    for (const auto& [f, r] : key.interiorRadii) {
      const auto [it, fresh] = radius.insert({f, {r, key.name}});
      if (!fresh && it->second.first != r)
        throw at.in("key " + inQuotes(key.name)).in("interior feature " + inQuotes(f)).in("radius")
            .error("is " + shortNumber(r) + " here and " + shortNumber(it->second.first) + " in key " +
                   inQuotes(it->second.second) + ": the disc moves rigidly, so it has one radius; give it once or the same in every key");
    }
  for (KeySpec& key : scene.keys)
    for (const auto& [f, r] : radius) key.interiorRadii[f] = r.first;
}

}  // namespace

std::vector<std::string> cutFeatureNames(const std::string& cut, CutKind kind) {
  switch (kind) {
    case CutKind::kNotch: return {cut + ".left", cut + ".right", cut + ".tip"};
    case CutKind::kSplit: return {cut + ".start.left", cut + ".start.right", cut + ".end.left", cut + ".end.right"};
    case CutKind::kSlit: return {cut + ".start", cut + ".end"};
  }
  return {};
}

int Scene::keyIndex(const std::string& name) const {
  for (size_t k = 0; k < keys.size(); ++k)
    if (keys[k].name == name) return static_cast<int>(k);
  return -1;
}

namespace {

// nlohmann's syntax error said for a person: where (line, column) without the exception's code,
// what was expected, and (unless nlohmann quotes what it last read) the text of that line around
// the column, which is where to look, with the usual cause.
std::string syntaxError(const json::parse_error& e, const std::string& source) {
  std::string what = e.what();
  const std::string at = "parse error at ";
  if (const size_t p = what.find(at); p != std::string::npos) what = what.substr(p + at.size());
  if (what.find("last read: ") != std::string::npos) return "malformed JSON at " + what;  // quotes the text itself
  const size_t end = std::min(source.size(), static_cast<size_t>(e.byte));
  const size_t lineStart = end == 0 ? 0 : source.rfind('\n', end - 1) + 1;  // npos + 1 = 0
  const size_t lineEnd = std::min(source.find('\n', lineStart), source.size());
  const size_t from = std::max(lineStart, end > 40 ? end - 40 : 0);
  std::string excerpt = source.substr(from, std::min(lineEnd, end + 20) - from);
  while (!excerpt.empty() && std::isspace(static_cast<unsigned char>(excerpt.front()))) excerpt.erase(0, 1);
  while (!excerpt.empty() && std::isspace(static_cast<unsigned char>(excerpt.back()))) excerpt.pop_back();
  for (char& c : excerpt)
    if (static_cast<unsigned char>(c) < 32) c = ' ';
  return "malformed JSON at " + what + (excerpt.empty() ? "" : "; there the text reads `" + excerpt + "`") +
         " (a missing or extra comma, or an unquoted name, is the usual cause)";
}

}  // namespace

Scene parseScene(const std::string& source, const std::string& path) {
  const Context at{std::filesystem::path(path).filename().string(), ""};
  // nlohmann's parser ends the text at a NUL byte; JSON text holds none, so neither does a scene.
  if (const size_t nul = source.find('\0'); nul != std::string::npos)
    throw at.error("malformed JSON: a NUL byte at offset " + std::to_string(nul) + " (a scene file is text)");
  json j;
  try {
    j = json::parse(source);
  } catch (const json::parse_error& e) {
    throw at.error(syntaxError(e, source));
  } catch (const json::out_of_range& e) {  // a number past the doubles (1e999)
    throw at.error(std::string("malformed JSON: a number too large for a double: ") + e.what());
  }
  std::set<std::string> allowed = parameterFields("");
  allowed.insert({"version", "reference", "keys", "tracing", "solver", "timeline", "dynamics", "stiffness"});
  requireObject(j, at, allowed);
  for (const char* section : {"tracing", "solver", "dynamics"})
    if (j.contains(section)) requireObject(j[section], at.in(section), parameterFields(section));
  if (!j.contains("version") || !j["version"].is_number_integer() || j["version"].get<int>() != 1)
    throw at.in("version").error("must be 1 (the only scene format version so far)");
  Scene scene;
  scene.file = path;
  if (!j.contains("keys") || !j["keys"].is_array() || j["keys"].empty())
    throw at.in("keys").error("needs at least one key");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (size_t k = 0; k < j["keys"].size(); ++k) {
    scene.keys.push_back(parseKey(j["keys"][k], at, folder, k));
    if (scene.keyIndex(scene.keys.back().name) != static_cast<int>(scene.keys.size()) - 1)
      throw at.in("key " + inQuotes(scene.keys.back().name)).error("is named twice");
  }
  if (j.contains("reference")) {
    scene.reference = j["reference"].is_string() ? scene.keyIndex(j["reference"].get<std::string>()) : -1;
    if (scene.reference < 0) {
      std::vector<std::string> names;
      for (const KeySpec& key : scene.keys) names.push_back(key.name);
      throw at.in("reference").error("must name one of the keys" +
                                     (j["reference"].is_string() ? didYouMean(j["reference"].get<std::string>(), names) : ""));
    }
  }
  readParameters(j, at, scene);
  checkCorrespondence(scene, at);
  checkInteriorFeatures(scene, at);
  shareInteriorRadii(scene, at);
  std::vector<std::string> names;
  for (const KeySpec& key : scene.keys) names.push_back(key.name);
  scene.timeline = parseTimeline(j.contains("timeline") ? &j["timeline"] : nullptr, names, scene.timelineSettings, at.file);
  if (j.contains("stiffness")) scene.stiffness = parseStiffness(j["stiffness"], at.in("stiffness"), names, folder.string());
  if (scene.keys.size() == 1)
    scene.notes.push_back(at.file + ": one key (" + inQuotes(scene.keys[0].name) +
                          "): the animation is a still, every frame that key's drawing; add keys to animate");
  return scene;
}

std::string readSceneFile(const std::string& path) {
  std::error_code error;
  const std::filesystem::path inside = std::filesystem::path(path) / "scene.json";
  if (std::filesystem::is_directory(path, error) && std::filesystem::exists(inside, error))
    throw InputError(path + ": is a folder; the scene is its file " + inside.string());
  return readFile(path);
}

Scene loadScene(const std::string& path) { return parseScene(readSceneFile(path), path); }

}  // namespace ib
