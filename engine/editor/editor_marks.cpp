#include "editor/editor_marks.h"

#include "pipeline/key_outlines.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace ib::editor {

namespace {

using nlohmann::json;

bool readPoint(const json& j, Eigen::Vector2d& out) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) return false;
  out = {j[0].get<double>(), j[1].get<double>()};
  return true;
}

Polyline readPoints(const json& j) {
  Polyline out;
  if (!j.is_array()) return out;
  for (const json& p : j) {
    Eigen::Vector2d q;
    if (readPoint(p, q)) out.push_back(q);
  }
  return out;
}

CutKind kindOf(const std::string& kind) {
  return kind == "split" ? CutKind::kSplit : kind == "slit" ? CutKind::kSlit : CutKind::kNotch;
}

Eigen::Vector2d pointAt(const Polyline& loop, double at) {
  const size_t i = static_cast<size_t>(std::floor(at)) % loop.size();
  const double t = at - std::floor(at);
  return (1 - t) * loop[i] + t * loop[(i + 1) % loop.size()];
}

// The loop from parameter `from` forward to `to` (wrapping), ends included.
Polyline piece(const Polyline& loop, double from, double to) {
  const double n = static_cast<double>(loop.size());
  if (to <= from) to += n;
  Polyline out{pointAt(loop, from)};
  for (double v = std::floor(from) + 1; v < to; v += 1) out.push_back(loop[static_cast<size_t>(v) % loop.size()]);
  out.push_back(pointAt(loop, to));
  return out;
}

}  // namespace

int DocumentMarks::keyIndex(const std::string& name) const {
  for (size_t k = 0; k < keys.size(); ++k)
    if (keys[k].name == name) return static_cast<int>(k);
  return -1;
}

DocumentMarks marksOf(const std::string& text) {
  DocumentMarks out;
  const json j = json::parse(text, nullptr, false);
  if (!j.is_object()) return out;
  if (j.contains("keys") && j["keys"].is_array())
    for (const json& k : j["keys"]) {
      if (!k.is_object()) continue;
      KeyMarks key;
      if (k.contains("name") && k["name"].is_string()) key.name = k["name"];
      if (k.contains("drawing") && k["drawing"].is_string()) key.drawing = k["drawing"];
      if (k.contains("features") && k["features"].is_object())
        for (const auto& [name, at] : k["features"].items()) {
          Eigen::Vector2d p;
          if (readPoint(at, p)) key.features[name] = p;
        }
      if (k.contains("interior_features") && k["interior_features"].is_object())
        for (const auto& [name, value] : k["interior_features"].items()) {
          Eigen::Vector2d p;
          if (readPoint(value, p)) key.interior[name] = p;
          if (value.is_object() && value.contains("at") && readPoint(value["at"], p)) {
            key.interior[name] = p;
            if (value.contains("radius") && value["radius"].is_number()) key.radii[name] = value["radius"].get<double>();
          }
        }
      if (k.contains("cuts") && k["cuts"].is_array())
        for (const json& c : k["cuts"]) {
          if (!c.is_object() || !c.contains("name") || !c["name"].is_string()) continue;
          CutMark cut{c["name"], c.contains("kind") && c["kind"].is_string() ? c["kind"].get<std::string>() : "notch", {}};
          if (c.contains("points")) cut.points = readPoints(c["points"]);
          key.cuts.push_back(cut);
        }
      out.keys.push_back(key);
    }
  if (j.contains("reference") && j["reference"].is_string()) out.reference = j["reference"];
  else if (!out.keys.empty()) out.reference = out.keys.front().name;
  if (j.contains("stiffness") && j["stiffness"].is_object() && j["stiffness"].contains("strokes") &&
      j["stiffness"]["strokes"].is_array())
    for (const json& s : j["stiffness"]["strokes"]) {
      if (!s.is_object()) continue;
      StrokeMark stroke;
      if (s.contains("name") && s["name"].is_string()) stroke.name = s["name"];
      if (s.contains("key") && s["key"].is_string()) stroke.key = s["key"];
      if (s.contains("points")) stroke.points = readPoints(s["points"]);
      if (s.contains("radius") && s["radius"].is_number()) stroke.radius = s["radius"];
      if (s.contains("kappa") && s["kappa"].is_number()) stroke.kappa = s["kappa"];
      out.strokes.push_back(stroke);
    }
  if (j.contains("timeline") && j["timeline"].is_object() && j["timeline"].contains("marks") && j["timeline"]["marks"].is_array())
    for (const json& m : j["timeline"]["marks"]) {
      const bool named = m.is_object() && m.contains("ease");
      out.markEases.push_back(!named ? "linear" : m["ease"].is_string() ? m["ease"].get<std::string>() : m["ease"].dump());
    }
  return out;
}

std::vector<MissingFeature> missingFeatures(const DocumentMarks& marks, int after) {
  const int m = static_cast<int>(marks.keys.size());
  // Each name some key needs: placed features everywhere; a cut's features where it is open.
  std::set<std::string> outline, interior;
  std::map<std::string, std::set<std::string>> cutFeatures;  // cut feature -> keys drawing the cut (not asked there)
  for (const KeyMarks& k : marks.keys) {
    for (const auto& [name, p] : k.features) outline.insert(name);
    for (const auto& [name, p] : k.interior) interior.insert(name);
    for (const CutMark& c : k.cuts)
      for (const std::string& f : cutFeatureNames(c.name, kindOf(c.kind))) cutFeatures[f].insert(k.name);
  }
  std::vector<MissingFeature> out;
  for (int step = 1; step <= m; ++step) {
    const KeyMarks& k = marks.keys[static_cast<size_t>(((after + step) % m + m) % m)];
    for (const std::string& name : outline)
      if (!k.features.count(name) && !(cutFeatures.count(name) && cutFeatures[name].count(k.name))) out.push_back({name, k.name, false});
    for (const auto& [name, closedIn] : cutFeatures)
      if (!outline.count(name) && !closedIn.count(k.name) && !k.features.count(name)) out.push_back({name, k.name, false});
    for (const std::string& name : interior)
      if (!k.interior.count(name)) out.push_back({name, k.name, true});
  }
  return out;
}

std::vector<OutlineArc> outlineArcs(const std::vector<Outline>& outlines, const std::map<std::string, Eigen::Vector2d>& features,
                                    std::map<std::pair<std::string, std::string>, int>& pairColour, double onOutline) {
  std::vector<const Polyline*> loops;
  for (const Outline& o : outlines) {
    loops.push_back(&o.outer);
    for (const Polyline& h : o.holes) loops.push_back(&h);
  }
  // Each feature on its nearest loop, if close enough.
  std::vector<std::vector<std::pair<double, std::string>>> on(loops.size());
  for (const auto& [name, p] : features) {
    int bestLoop = -1;
    LoopPoint best;
    for (size_t l = 0; l < loops.size(); ++l) {
      if (loops[l]->size() < 2) continue;
      const LoopPoint o = nearestOnLoop(*loops[l], p);
      if (o.distance < best.distance) best = o, bestLoop = static_cast<int>(l);
    }
    if (bestLoop >= 0 && best.distance <= onOutline) on[static_cast<size_t>(bestLoop)].push_back({best.at, name});
  }
  std::vector<OutlineArc> out;
  for (size_t l = 0; l < loops.size(); ++l) {
    const Polyline& loop = *loops[l];
    if (loop.size() < 2) continue;
    auto& marks = on[l];
    std::sort(marks.begin(), marks.end());
    if (marks.size() < 2) {
      OutlineArc whole;
      whole.points = loop;
      whole.points.push_back(loop.front());
      out.push_back(whole);
      continue;
    }
    for (size_t i = 0; i < marks.size(); ++i) {
      const auto& [fromAt, from] = marks[i];
      const auto& [toAt, to] = marks[(i + 1) % marks.size()];
      OutlineArc arc{from, to, piece(loop, fromAt, toAt), -1, false};
      const auto key = std::make_pair(from, to);  // in the loop's direction: the two arcs between two features differ
      auto it = pairColour.find(key);
      if (it == pairColour.end()) it = pairColour.emplace(key, static_cast<int>(pairColour.size())).first;
      arc.colour = it->second;
      out.push_back(arc);
    }
  }
  return out;
}

std::string orderProblems(const DocumentMarks& marks, std::vector<std::vector<OutlineArc>>& arcs) {
  std::string message;
  const size_t m = std::min(marks.keys.size(), arcs.size());
  // Each key's features in the order its loops pass them: arcs run from one to the next.
  std::vector<std::map<std::string, std::string>> next(m);
  for (size_t k = 0; k < m; ++k)
    for (const OutlineArc& arc : arcs[k])
      if (!arc.from.empty()) next[k][arc.from] = arc.to;
  for (size_t k = 0; k < m; ++k)
    for (OutlineArc& arc : arcs[k]) {
      if (arc.from.empty()) continue;
      for (size_t other = 0; other < m; ++other) {
        if (other == k || !next[other].count(arc.from) || !next[other].count(arc.to)) continue;
        // In the other key, the feature after `from` among those this key places too must be `to`.
        std::string after = next[other][arc.from];
        for (size_t guard = 0; guard < next[other].size() && !next[k].count(after); ++guard) after = next[other][after];
        if (after == arc.to) continue;
        arc.unmatched = true;
        if (message.empty())
          message = "features `" + arc.from + "` and `" + arc.to + "` follow each other round key `" + marks.keys[k].name +
                    "`'s outline, not round key `" + marks.keys[other].name + "`'s: place them in the same order round every key";
      }
    }
  return message;
}

}  // namespace ib::editor
