#include "core/json_layout_scan.h"

namespace ib::json_layout {

namespace {

// A recursive-descent pass over the text that records spans and no values: the values themselves
// come from nlohmann's parser, which rewriteJson runs on the same text.
class Scanner {
 public:
  explicit Scanner(const std::string& text) : text_(text) {}

  // The whole text: an optional byte order mark, white space, one value, white space.
  std::vector<ScannedValue> document() {
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;
    skipSpace();
    if (!value(0)) return {};
    skipSpace();
    if (pos_ != text_.size()) return {};
    return std::move(values_);
  }

 private:
  // The byte at the cursor, or '\0' at the end (which no token starts with or expects).
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }

  bool digitAtCursor() const { return peek() >= '0' && peek() <= '9'; }

  // JSON's white space: space, tab, line feed, carriage return.
  void skipSpace() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return;
      ++pos_;
    }
  }

  // The value at the cursor, appended to values_ before the values inside it; `depth` counts the
  // containers around it, so that nesting is capped before the recursion can exhaust the stack.
  bool value(int depth) {
    const size_t index = values_.size();
    values_.emplace_back();
    values_[index].begin = pos_;
    bool ok = false;
    switch (peek()) {
      case '{':
      case '[':
        values_[index].kind = peek() == '{' ? ValueKind::Object : ValueKind::Array;
        ok = depth < kMaxJsonDepth && container(index, depth);
        break;
      case '"':
        values_[index].kind = ValueKind::String;
        ok = string();
        break;
      case 't':
        ok = literal("true");
        break;
      case 'f':
        ok = literal("false");
        break;
      case 'n':
        ok = literal("null");
        break;
      default:
        values_[index].kind = ValueKind::Number;
        ok = number();
    }
    values_[index].end = pos_;
    return ok;
  }

  // An object or an array at the cursor, with the span of each member or element and of the text
  // between them.
  bool container(size_t index, int depth) {
    const bool object = peek() == '{';
    const char close = object ? '}' : ']';
    ++pos_;
    std::vector<Part> parts;
    size_t before = pos_;
    skipSpace();
    if (peek() == close) {
      ++pos_;
      return true;
    }
    while (true) {
      Part part;
      part.before = before;
      part.key = pos_;
      if (object) {
        if (peek() != '"' || !string()) return false;
        part.keyEnd = pos_;
        skipSpace();
        if (peek() != ':') return false;
        ++pos_;
        skipSpace();
      } else {
        part.keyEnd = pos_;
      }
      part.value = values_.size();
      if (!value(depth + 1)) return false;
      parts.push_back(part);
      before = pos_;
      skipSpace();
      if (peek() == ',') {
        ++pos_;
        skipSpace();
      } else if (peek() == close) {
        ++pos_;
        values_[index].parts = std::move(parts);
        return true;
      } else {
        return false;
      }
    }
  }

  // A string at its opening quote: no raw control characters, only JSON's escapes.
  bool string() {
    ++pos_;
    while (pos_ < text_.size()) {
      const unsigned char c = static_cast<unsigned char>(text_[pos_++]);
      if (c == '"') return true;
      if (c < 0x20) return false;
      if (c != '\\') continue;
      switch (peek()) {
        case '"':
        case '\\':
        case '/':
        case 'b':
        case 'f':
        case 'n':
        case 'r':
        case 't':
          ++pos_;
          break;
        case 'u':
          ++pos_;
          for (int i = 0; i < 4; ++i, ++pos_) {
            const char h = peek();
            if (!((h >= '0' && h <= '9') || (h >= 'a' && h <= 'f') || (h >= 'A' && h <= 'F'))) return false;
          }
          break;
        default:
          return false;
      }
    }
    return false;
  }

  // A number: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
  bool number() {
    if (peek() == '-') ++pos_;
    if (peek() == '0') {
      ++pos_;
    } else if (digitAtCursor()) {
      while (digitAtCursor()) ++pos_;
    } else {
      return false;
    }
    if (peek() == '.') {
      ++pos_;
      if (!digitAtCursor()) return false;
      while (digitAtCursor()) ++pos_;
    }
    if (peek() == 'e' || peek() == 'E') {
      ++pos_;
      if (peek() == '+' || peek() == '-') ++pos_;
      if (!digitAtCursor()) return false;
      while (digitAtCursor()) ++pos_;
    }
    return true;
  }

  // true, false or null, spelled out.
  bool literal(const std::string& word) {
    if (text_.compare(pos_, word.size(), word) != 0) return false;
    pos_ += word.size();
    return true;
  }

  const std::string& text_;
  size_t pos_ = 0;
  std::vector<ScannedValue> values_;
};

}  // namespace

std::vector<ScannedValue> scanJson(const std::string& text) { return Scanner(text).document(); }

}  // namespace ib::json_layout
