// Private to core/json_layout.cpp: where each value of a JSON text lies, so that rewriteJson can
// copy the text of the parts an edit did not touch (nlohmann's parser gives no positions).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace ib::json_layout {

enum class ValueKind { Object, Array, String, Number, Literal };

// A member of an object or an element of an array, as offsets into the text. The text before it,
// [before, key), is the white space after the opening bracket for the first part, else the white
// space and comma after the previous part's value; an object member's text between its key and its
// value, [keyEnd, value's begin), is the colon with the white space around it.
struct Part {
  size_t before = 0;
  size_t key = 0;     // an object member's key, at its opening quote; an array element's value
  size_t keyEnd = 0;  // just past the key's closing quote; == key for an array element
  size_t value = 0;   // the part's value: an index into the scanned values
};

// One value of the text: [begin, end) holds it, brackets or quotes included.
struct ScannedValue {
  ValueKind kind = ValueKind::Literal;
  size_t begin = 0, end = 0;
  std::vector<Part> parts;  // a container's members or elements, in the text's order
};

// Containers nested deeper than this make a text invalid: the scanner and the writer recurse.
constexpr int kMaxJsonDepth = 512;

// Every value of `text`, the top one first; empty unless text is one JSON value (RFC 8259, which
// nlohmann also checks UTF-8 against) with only white space around it after an optional UTF-8 byte
// order mark, nesting containers at most kMaxJsonDepth deep.
std::vector<ScannedValue> scanJson(const std::string& text);

}  // namespace ib::json_layout
