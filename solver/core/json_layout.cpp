#include "core/json_layout.h"

#include "core/json_layout_scan.h"

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ib {

namespace {

using Json = nlohmann::ordered_json;
using json_layout::Part;
using json_layout::ScannedValue;
using json_layout::ValueKind;
// An object's members in order, indexable (ordered_map hides the operator[] of the vector it is).
using Members = Json::object_t::Container;

// The house style breaks a new value over lines when its one-line form would end past this column.
constexpr size_t kLineWidth = 100;
// Arrays whose differing middles would need a larger table than this are matched by position.
constexpr size_t kMaxAlignmentCells = size_t(1) << 20;
constexpr size_t kNone = static_cast<size_t>(-1);

// A scalar, or a key, as nlohmann writes it; invalid UTF-8 is replaced rather than thrown on.
std::string dumpCompact(const Json& v) { return v.dump(-1, ' ', false, Json::error_handler_t::replace); }

bool isBlank(char c) { return c == ' ' || c == '\t'; }

bool isFilledContainer(const Json& v) { return (v.is_object() || v.is_array()) && !v.empty(); }

// Where the line holding out[pos] (or ending at pos) begins.
size_t lineStart(const std::string& out, size_t pos) {
  const size_t newline = pos == 0 ? std::string::npos : out.rfind('\n', pos - 1);
  return newline == std::string::npos ? 0 : newline + 1;
}

// Characters (UTF-8 code points) in out[from, to), for line widths.
size_t characters(const std::string& out, size_t from, size_t to) {
  size_t count = 0;
  for (size_t i = from; i < to; ++i) count += (static_cast<unsigned char>(out[i]) & 0xC0) != 0x80;
  return count;
}

// The white space that starts the line holding out[pos].
std::string lineIndent(const std::string& out, size_t pos) {
  size_t end = lineStart(out, pos);
  const size_t start = end;
  while (end < out.size() && isBlank(out[end])) ++end;
  return out.substr(start, end - start);
}

// White space that puts a new line's text in the column of out[pos]: the line's own indentation
// when out[pos] starts it, else that indentation followed by a space for each character up to pos.
std::string alignmentAt(const std::string& out, size_t pos) {
  const std::string indent = lineIndent(out, pos);
  const size_t textStart = lineStart(out, pos) + indent.size();
  if (textStart >= pos) return indent;
  return indent + std::string(characters(out, textStart, pos), ' ');
}

// Appends v on one line in the house style (", " between parts, ": " after keys); false, with part
// of it appended, as soon as it is certain to be wider than `width` characters.
bool appendOneLine(std::string& out, const Json& v, size_t start, size_t width) {
  if (out.size() - start > 4 * width) return false;  // a character takes at most 4 bytes
  if (!isFilledContainer(v)) {
    out += dumpCompact(v);
    return true;
  }
  const bool object = v.is_object();
  out += object ? '{' : '[';
  bool first = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (!first) out += ", ";
    first = false;
    if (object) out += dumpCompact(Json(it.key())) + ": ";
    if (!appendOneLine(out, it.value(), start, width)) return false;
  }
  out += object ? '}' : ']';
  return true;
}

// Appends a new value in the house style at the end of out: on one line when the line then ends by
// column kLineWidth, else one part a line, indented 2 spaces more than the line the value starts on.
void appendFresh(std::string& out, const Json& v, const std::string& lineBreak) {
  if (!isFilledContainer(v)) {
    out += dumpCompact(v);
    return;
  }
  const size_t mark = out.size();
  const size_t column = characters(out, lineStart(out, mark), mark);
  const size_t width = column < kLineWidth ? kLineWidth - column : 0;
  if (appendOneLine(out, v, mark, width) && characters(out, mark, out.size()) <= width) return;
  out.resize(mark);
  const bool object = v.is_object();
  const std::string outer = lineIndent(out, mark);
  const std::string inner = outer + "  ";
  out += object ? '{' : '[';
  bool first = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (!first) out += ',';
    first = false;
    out += lineBreak + inner;
    if (object) out += dumpCompact(Json(it.key())) + ": ";
    appendFresh(out, it.value(), lineBreak);
  }
  out += lineBreak + outer + (object ? '}' : ']');
}

// How an array element is written back: kept (equal, its text copied), changed (rewritten against
// the original element), added (written fresh) or dropped.
enum class StepKind { Keep, Change, Add, Drop };
struct Step {
  StepKind kind;
  size_t from, to;  // indices in the original array (Keep, Change, Drop) and the updated one (Keep, Change, Add)
};

// Matches the elements of `to` to those of `from`: equal runs at both ends are kept; in between, a
// longest common subsequence of equal elements is kept, and an unmatched pair in the same place is
// changed rather than dropped and added, so that an edited element keeps what it can of its text.
// Middles too long for the table are paired by position.
std::vector<Step> alignElements(const Json::array_t& from, const Json::array_t& to) {
  const size_t n = from.size(), m = to.size();
  size_t head = 0, tail = 0;
  while (head < n && head < m && from[head] == to[head]) ++head;
  while (tail < n - head && tail < m - head && from[n - 1 - tail] == to[m - 1 - tail]) ++tail;
  const size_t rows = n - head - tail, columns = m - head - tail;
  std::vector<Step> steps;
  for (size_t k = 0; k < head; ++k) steps.push_back({StepKind::Keep, k, k});
  // lcs[i * (columns + 1) + j]: the longest common subsequence of the middles from i and from j.
  std::vector<uint32_t> lcs;
  const bool table = rows + 1 <= kMaxAlignmentCells / (columns + 1);
  if (table) {
    lcs.assign((rows + 1) * (columns + 1), 0);
    for (size_t i = rows; i-- > 0;)
      for (size_t j = columns; j-- > 0;)
        lcs[i * (columns + 1) + j] = from[head + i] == to[head + j]
                                         ? lcs[(i + 1) * (columns + 1) + j + 1] + 1
                                         : std::max(lcs[(i + 1) * (columns + 1) + j], lcs[i * (columns + 1) + j + 1]);
  }
  const auto at = [&](size_t i, size_t j) { return lcs[i * (columns + 1) + j]; };
  size_t i = 0, j = 0;
  while (i < rows && j < columns) {
    if (!table) {
      steps.push_back({StepKind::Change, head + i++, head + j++});
    } else if (from[head + i] == to[head + j]) {
      steps.push_back({StepKind::Keep, head + i++, head + j++});
    } else if (at(i + 1, j + 1) == at(i, j)) {
      steps.push_back({StepKind::Change, head + i++, head + j++});
    } else if (at(i + 1, j) == at(i, j)) {
      steps.push_back({StepKind::Drop, head + i++, kNone});
    } else {
      steps.push_back({StepKind::Add, kNone, head + j++});
    }
  }
  for (; i < rows; ++i) steps.push_back({StepKind::Drop, head + i, kNone});
  for (; j < columns; ++j) steps.push_back({StepKind::Add, kNone, head + j});
  for (size_t k = tail; k-- > 0;) steps.push_back({StepKind::Keep, n - 1 - k, m - 1 - k});
  return steps;
}

// How a container's parts are laid out, for the parts an edit adds.
struct Layout {
  bool multiLine = false;        // some part starts after a line break
  std::string separator = ", ";  // between parts on one line: the original's own, if it has one
  std::string colon = ": ";      // between a key and its value: the first member's, if on one line
};

// Writes `updated` in the layout of the scanned text of `original` (see rewriteJson): walks the
// two values together, copying the text of whatever is equal.
class LayoutWriter {
 public:
  LayoutWriter(const std::string& text, const std::vector<ScannedValue>& values)
      : text_(text), values_(values), lineBreak_(lineBreakOf(text)) {}

  // The whole text: what surrounds the top value is kept.
  std::string write(const Json& original, const Json& updated) {
    out_.reserve(text_.size() + 256);
    const ScannedValue& top = values_[0];
    copy(0, top.begin);
    value(0, original, updated);
    copy(top.end, text_.size());
    return std::move(out_);
  }

 private:
  // "\r\n" when the text's lines end so, else "\n": the break that new lines are given.
  static std::string lineBreakOf(const std::string& text) {
    const size_t newline = text.find('\n');
    return newline != std::string::npos && newline > 0 && text[newline - 1] == '\r' ? "\r\n" : "\n";
  }

  // Appends text_[begin, end), original text kept as it was.
  void copy(size_t begin, size_t end) { out_.append(text_, begin, end - begin); }

  // Whether the scanned value is the kind of `original`, with as many parts: the scan and
  // nlohmann's parse read the same text, so they should always agree; if not, nothing is reused.
  static bool sameShape(const ScannedValue& scanned, const Json& original) {
    switch (scanned.kind) {
      case ValueKind::Object:
        return original.is_object() && scanned.parts.size() >= original.size() &&
               scanned.parts.empty() == original.empty();
      case ValueKind::Array:
        return original.is_array() && scanned.parts.size() == original.size();
      case ValueKind::String:
        return original.is_string();
      case ValueKind::Number:
        return original.is_number();
      case ValueKind::Literal:
        return original.is_boolean() || original.is_null();
    }
    return false;
  }

  // Writes `updated` where the scanned value `index` (which parses to `original`) was: its text
  // when equal, a rebuilt container when both are filled containers of one kind, else fresh text.
  void value(size_t index, const Json& original, const Json& updated) {
    const ScannedValue& scanned = values_[index];
    if (!sameShape(scanned, original)) {
      appendFresh(out_, updated, lineBreak_);
    } else if (original == updated) {
      copy(scanned.begin, scanned.end);
    } else if (scanned.kind == ValueKind::Object && updated.is_object() && !original.empty() && !updated.empty()) {
      const std::vector<size_t> parts = partsOf(scanned, original.get_ref<const Json::object_t&>());
      if (parts.empty())
        appendFresh(out_, updated, lineBreak_);
      else
        object(scanned, parts, original.get_ref<const Json::object_t&>(), updated.get_ref<const Json::object_t&>());
    } else if (scanned.kind == ValueKind::Array && updated.is_array() && !original.empty() && !updated.empty()) {
      array(scanned, original.get_ref<const Json::array_t&>(), updated.get_ref<const Json::array_t&>());
    } else {
      appendFresh(out_, updated, lineBreak_);
    }
  }

  // The separators, colon and line breaks of a scanned container.
  Layout layoutOf(const ScannedValue& scanned) const {
    Layout layout;
    for (size_t p = 0; p < scanned.parts.size(); ++p) {
      const std::string_view gap(text_.data() + scanned.parts[p].before, scanned.parts[p].key - scanned.parts[p].before);
      if (gap.find('\n') != std::string_view::npos) layout.multiLine = true;
      if (p == 1) layout.separator = std::string(gap);
    }
    if (scanned.kind == ValueKind::Object) {
      const Part& first = scanned.parts[0];
      const std::string colon = text_.substr(first.keyEnd, values_[first.value].begin - first.keyEnd);
      if (colon.find('\n') == std::string::npos) layout.colon = colon;
    }
    return layout;
  }

  // The text before a part that has no original separator of its own: on one line, the
  // container's separator; across lines, a comma, a line break and the column of `lineFirst`, the
  // first part on the line of the previous one (its siblings' indentation, when several share a line).
  std::string newSeparator(const Layout& layout, size_t lineFirst) const {
    return layout.multiLine ? "," + lineBreak_ + alignmentAt(out_, lineFirst) : layout.separator;
  }

  // Writes the text before the part written `written`-th: the container's opening white space for
  // the first, the original separator of a part that had one, else a new one. Keeps `lineFirst`,
  // where in out_ the first part on the line of the last part written begins.
  void separator(const ScannedValue& scanned, size_t written, const Part* part, bool ownSeparator,
                 const Layout& layout, size_t& lineFirst) {
    if (written == 0)
      copy(scanned.parts[0].before, scanned.parts[0].key);
    else if (part && ownSeparator)
      copy(part->before, part->key);
    else
      out_ += newSeparator(layout, lineFirst);
    const size_t start = out_.size();
    if (written == 0 || (layout.multiLine && lineStart(out_, start) != lineStart(out_, lineFirst))) lineFirst = start;
  }

  // For each member of `original`, the scanned part it was read from: the part at the same place,
  // or, when keys repeat (nlohmann keeps the first place and the last value), the last part with
  // its key. Empty when the scan and the parse disagree.
  std::vector<size_t> partsOf(const ScannedValue& scanned, const Members& original) const {
    std::vector<size_t> parts(original.size());
    if (scanned.parts.size() == original.size()) {
      for (size_t t = 0; t < parts.size(); ++t) {
        const Part& part = scanned.parts[t];
        const std::string_view raw(text_.data() + part.key + 1, part.keyEnd - part.key - 2);
        if (raw.find('\\') == std::string_view::npos && raw != original[t].first) return {};
        parts[t] = t;
      }
      return parts;
    }
    std::unordered_map<std::string, size_t> last;
    for (size_t p = 0; p < scanned.parts.size(); ++p) {
      const Json key = Json::parse(text_.substr(scanned.parts[p].key, scanned.parts[p].keyEnd - scanned.parts[p].key),
                                   nullptr, false);
      if (key.is_string()) last[key.get<std::string>()] = p;
    }
    for (size_t t = 0; t < parts.size(); ++t) {
      const auto it = last.find(original[t].first);
      if (it == last.end()) return {};
      parts[t] = it->second;
    }
    return parts;
  }

  // Rebuilds an object, whose members were read from the scanned `parts` (partsOf): members in
  // updated's order, each with its original text where its key was there (its value rewritten
  // against the original one). A member with a new key where the next original member's key is gone
  // takes that member's place (a rename): its separator, colon and what can be kept of its value.
  // Other new members are written fresh.
  void object(const ScannedValue& scanned, const std::vector<size_t>& parts, const Members& original,
              const Members& updated) {
    std::unordered_map<std::string_view, size_t> byKey;
    for (size_t t = 0; t < original.size(); ++t) byKey.emplace(original[t].first, t);
    std::vector<size_t> match(updated.size(), kNone);
    std::vector<bool> taken(original.size(), false);
    for (size_t j = 0; j < updated.size(); ++j) {
      const auto it = byKey.find(updated[j].first);
      if (it == byKey.end()) continue;
      match[j] = it->second;
      taken[it->second] = true;
    }
    const Layout layout = layoutOf(scanned);
    out_ += '{';
    size_t previousOriginal = kNone, lineFirst = 0;
    for (size_t j = 0; j < updated.size(); ++j) {
      size_t t = match[j];
      const size_t next = previousOriginal == kNone ? 0 : previousOriginal + 1;
      const bool renamed = t == kNone && next < original.size() && !taken[next];
      if (renamed) taken[t = next] = true;
      const Part* part = t == kNone ? nullptr : &scanned.parts[parts[t]];
      separator(scanned, j, part, part && parts[t] > 0, layout, lineFirst);
      if (part && !renamed)
        copy(part->key, part->keyEnd);
      else
        out_ += dumpCompact(Json(updated[j].first));
      if (part) {
        copy(part->keyEnd, values_[part->value].begin);
        value(part->value, original[t].second, updated[j].second);
        previousOriginal = t;
      } else {
        out_ += layout.colon;
        appendFresh(out_, updated[j].second, lineBreak_);
      }
    }
    copy(values_[scanned.parts.back().value].end, scanned.end - 1);
    out_ += '}';
  }

  // Rebuilds an array: elements matched by alignElements keep their text and separators, changed
  // ones are rewritten against the original element, added ones are written fresh.
  void array(const ScannedValue& scanned, const Json::array_t& original, const Json::array_t& updated) {
    const Layout layout = layoutOf(scanned);
    out_ += '[';
    size_t written = 0, lineFirst = 0;
    for (const Step& step : alignElements(original, updated)) {
      if (step.kind == StepKind::Drop) continue;
      const Part* part = step.kind == StepKind::Add ? nullptr : &scanned.parts[step.from];
      separator(scanned, written++, part, part && step.from > 0, layout, lineFirst);
      if (step.kind == StepKind::Keep)
        copy(part->key, values_[part->value].end);
      else if (step.kind == StepKind::Change)
        value(part->value, original[step.from], updated[step.to]);
      else
        appendFresh(out_, updated[step.to], lineBreak_);
    }
    copy(values_[scanned.parts.back().value].end, scanned.end - 1);
    out_ += ']';
  }

  const std::string& text_;
  const std::vector<ScannedValue>& values_;
  const std::string lineBreak_;
  std::string out_;
};

}  // namespace

std::string rewriteJson(const std::string& original, const nlohmann::ordered_json& updated) {
  const std::vector<ScannedValue> values = json_layout::scanJson(original);
  if (!values.empty() && values[0].kind == ValueKind::Object) {
    const Json parsed = Json::parse(original, nullptr, false);
    if (parsed.is_object()) return LayoutWriter(original, values).write(parsed, updated);
  }
  return updated.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace ib
