#include "scene/edit_ops.h"

#include "core/error.h"
#include "core/suggest.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

namespace ib {

namespace {

using Json = nlohmann::json;

// Reads the fields of one operation, naming the file, the operation and the field in messages.
class OpReader {
 public:
  OpReader(const Json& op, int index, std::string where) : op_(op), index_(index), where_(std::move(where)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(where_ + ": operation " + std::to_string(index_) + " (" + name() + "): " +
                     (field.empty() ? "" : "field " + inQuotes(field) + ": ") + what);
  }
  std::string name() const { return op_.contains("op") && op_["op"].is_string() ? op_["op"].get<std::string>() : "?"; }
  bool has(const std::string& field) const { return op_.contains(field); }

  std::string text(const std::string& field) const {
    if (!has(field)) fail(field, "missing: give it as a string");
    if (!op_[field].is_string() || op_[field].get<std::string>().empty()) fail(field, "expected a non-empty string");
    return op_[field].get<std::string>();
  }
  std::string optionalText(const std::string& field) const { return has(field) ? text(field) : std::string(); }
  double number(const std::string& field) const {
    if (!has(field)) fail(field, "missing: give it as a number");
    if (!op_[field].is_number() || !std::isfinite(op_[field].get<double>())) fail(field, "expected a finite number");
    return op_[field].get<double>();
  }
  double positive(const std::string& field) const {
    const double value = number(field);
    if (!(value > 0)) fail(field, "must be greater than 0 (got " + op_[field].dump() + ")");
    return value;
  }
  static bool isPoint(const Json& p) {
    return p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number() &&
           std::isfinite(p[0].get<double>()) && std::isfinite(p[1].get<double>());
  }
  edit::Point point(const std::string& field) const {
    if (!has(field)) fail(field, "missing: give it as [x, y] in drawing pixels");
    if (!isPoint(op_[field])) fail(field, "expected [x, y] in drawing pixels, finite numbers (got " + op_[field].dump() + ")");
    return {op_[field][0].get<double>(), op_[field][1].get<double>()};
  }
  edit::Points points(const std::string& field, size_t least) const {
    if (!has(field)) fail(field, "missing: give it as [[x, y], ...] in drawing pixels");
    const Json& list = op_[field];
    if (!list.is_array() || list.size() < least)
      fail(field, "expected a list of at least " + std::to_string(least) + " points [x, y] in drawing pixels");
    edit::Points out;
    for (size_t i = 0; i < list.size(); ++i) {
      if (!isPoint(list[i])) fail(field, "point " + std::to_string(i) + ": expected [x, y], finite numbers (got " + list[i].dump() + ")");
      out.emplace_back(list[i][0].get<double>(), list[i][1].get<double>());
    }
    return out;
  }
  // Every field of the operation must be one it takes: a misspelt optional field would be ignored.
  void only(std::initializer_list<const char*> fields) const {
    std::vector<std::string> known{"op"};
    for (const char* f : fields) known.emplace_back(f);
    for (auto it = op_.begin(); it != op_.end(); ++it)
      if (std::find(known.begin(), known.end(), it.key()) == known.end())
        fail(it.key(), "not a field of " + name() + didYouMean(it.key(), known));
  }

 private:
  const Json& op_;
  int index_;
  std::string where_;
};

EditOp readOp(const Json& j, int index, const std::string& where) {
  const OpReader r(j, index, where);
  if (!j.is_object()) r.fail("", "expected an object {\"op\": NAME, ...} (got " + j.dump() + ")");
  EditOp op;
  op.index = index;
  op.op = r.text("op");
  const std::string& o = op.op;
  if (o == "add_key") {
    r.only({"name", "drawing"});
    op.edit = edit::AddKey{r.text("name"), r.text("drawing")};
  } else if (o == "remove_key") {
    r.only({"name"});
    op.edit = edit::RemoveKey{r.text("name")};
  } else if (o == "add_feature" || o == "move_feature") {
    r.only({"key", "name", "at"});
    op.edit = edit::SetFeature{r.text("key"), r.text("name"), r.point("at")};
    op.snapsToOutline = true;
  } else if (o == "remove_feature") {
    r.only({"key", "name"});
    op.edit = edit::RemoveFeature{r.text("name"), r.optionalText("key")};
  } else if (o == "rename_feature") {
    r.only({"name", "to"});
    op.edit = edit::RenameFeature{r.text("name"), r.text("to")};
  } else if (o == "add_interior_feature" || o == "move_interior_feature") {
    r.only({"key", "name", "at", "radius"});
    op.edit = edit::SetInteriorFeature{r.text("key"), r.text("name"), r.point("at"),
                                       r.has("radius") ? std::optional<double>(r.positive("radius")) : std::nullopt};
  } else if (o == "set_interior_radius") {
    r.only({"name", "radius"});
    op.edit = edit::SetInteriorRadius{r.text("name"), r.positive("radius")};
  } else if (o == "remove_interior_feature") {
    r.only({"key", "name"});
    op.edit = edit::RemoveInteriorFeature{r.text("name"), r.optionalText("key")};
  } else if (o == "add_cut") {
    r.only({"key", "name", "kind", "points"});
    const std::string kind = r.text("kind");
    if (kind != "notch" && kind != "split" && kind != "slit") r.fail("kind", "expected \"notch\", \"split\" or \"slit\" (got " + inQuotes(kind) + ")");
    op.edit = edit::AddCut{r.text("key"), r.text("name"), kind, r.points("points", 2)};
  } else if (o == "remove_cut") {
    r.only({"key", "name"});
    op.edit = edit::RemoveCut{r.text("name"), r.optionalText("key")};
  } else if (o == "paint_stiffness") {
    r.only({"key", "name", "points", "radius", "kappa"});
    const std::string name = r.has("name") ? r.text("name") : "paint " + std::to_string(index + 1);
    op.edit = edit::AddStiffnessStroke{name, r.text("key"), r.points("points", 1), r.positive("radius"), r.positive("kappa")};
  } else if (o == "add_mark") {
    r.only({"time", "key", "ease"});
    edit::AddMark mark{r.number("time"), r.text("key")};
    if (r.has("ease")) mark.ease = j["ease"].dump();
    op.edit = mark;
  } else if (o == "move_mark" || o == "set_mark_key" || o == "set_mark_ease") {
    r.only({"index", o == "move_mark" ? "time" : o == "set_mark_key" ? "key" : "ease"});
    const double index = r.number("index");
    if (index < 0 || index != std::floor(index)) r.fail("index", "expected a mark's index in time order, from 0");
    const int i = static_cast<int>(index);
    if (o == "move_mark") op.edit = edit::MoveMark{i, r.number("time")};
    else if (o == "set_mark_key") op.edit = edit::SetMarkKey{i, r.text("key")};
    else op.edit = edit::SetMarkEase{i, r.has("ease") && !j["ease"].is_null() ? j["ease"].dump() : std::string()};
  } else if (o == "set_reference") {
    r.only({"key"});
    op.edit = edit::SetReference{r.text("key")};
  } else if (o == "set_drawing") {
    r.only({"key", "drawing"});
    op.edit = edit::SetKeyDrawing{r.text("key"), r.text("drawing")};
  } else if (o == "set_cut_release") {
    r.only({"cut", "release"});
    std::optional<double> release;
    if (r.has("release") && !j["release"].is_null()) release = r.number("release");
    op.edit = edit::SetCutRelease{r.text("cut"), release};
  } else if (o == "set") {
    r.only({"name", "value"});
    if (!r.has("value") || !(j["value"].is_number() || j["value"].is_string() || j["value"].is_boolean()))
      r.fail("value", "expected a number, or a word for a choice (see `inbetween parameters`)");
    const Json& v = j["value"];
    op.assignment = r.text("name") + "=" + (v.is_string() ? v.get<std::string>() : v.is_boolean() ? (v.get<bool>() ? "on" : "off") : v.dump());
  } else {
    r.fail("op", "unknown operation " + inQuotes(o) + didYouMean(o, editOpNames()));
  }
  return op;
}

}  // namespace

const std::vector<std::string>& editOpNames() {
  static const std::vector<std::string> names{
      "add_key", "remove_key", "add_feature", "move_feature", "remove_feature", "rename_feature",
      "add_interior_feature", "move_interior_feature", "set_interior_radius", "remove_interior_feature", "add_cut", "remove_cut",
      "paint_stiffness", "add_mark", "move_mark", "set_mark_key", "set_mark_ease", "set_reference", "set_drawing",
      "set_cut_release", "set"};
  return names;
}

std::vector<EditOp> readEditOps(const std::string& text, const std::string& file) {
  const std::string where = std::filesystem::path(file).filename().string();
  const Json ops = Json::parse(text, nullptr, false);
  if (ops.is_discarded()) throw InputError(where + ": not JSON: write a JSON array of operations, [{\"op\": ...}, ...]");
  if (!ops.is_array()) throw InputError(where + ": expected a JSON array of operations, [{\"op\": ...}, ...]");
  std::vector<EditOp> out;
  for (size_t i = 0; i < ops.size(); ++i) out.push_back(readOp(ops[i], static_cast<int>(i), where));
  return out;
}

}  // namespace ib
