// Writing an edited scene file back in the layout it was read in, so that one edit is a small diff.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace ib {

// Writes `updated` as JSON text in the layout of `original`, the text it was read from (and edited since):
// - rewriteJson(original, nlohmann::ordered_json::parse(original)) == original, byte for byte;
// - every value whose JSON is unchanged keeps its original text (spelling of numbers and strings, spacing, line breaks);
// - a changed scalar is replaced in place; the text around it stays;
// - object members keep their original text and separators; members are written in updated's order
//   (ordered_json keeps the file's order on parse, so an edit that adds a member appends it);
//   a removed member goes with its separating comma and the white space before it; an added member
//   follows the layout of its siblings (on the same line after ", " when the object is on one line;
//   on a new line with the previous member's indentation when it spans lines);
// - arrays: elements are matched to the original's by equality in order (longest common subsequence),
//   so inserting or removing one element (a cut point, a timeline mark, a key) keeps the others' text;
//   added elements follow their siblings' layout as for members;
// - a new value (or one replaced wholesale, e.g. a different type) is written in the house style:
//   scalars as nlohmann dumps them, arrays of scalars and small objects on one line ("[64, 28]",
//   {"name": "x", "key": "y"} with ", " and ": "), a value whose one-line form would make the line longer than
//   100 characters broken over lines, indented 2 more spaces than the line it starts on;
// - if `original` is not valid JSON or not an object at the top, the result is updated.dump(2) + "\n".
// Output is always valid JSON that parses to `updated` (nlohmann::ordered_json::parse(result) == updated).
std::string rewriteJson(const std::string& original, const nlohmann::ordered_json& updated);

}  // namespace ib
