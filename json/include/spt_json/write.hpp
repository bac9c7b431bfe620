// Writing JSON: a document is built as nlohmann-json's ordered_json (members stay in the order
// they were added, which is the order spt's outputs have always had) and printed by dump(), so
// every JSON output of spt has one number form and one string form.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace spt::json {

using Doc = nlohmann::ordered_json;

// A measured value (PSNR, seconds, rates) as spt writes it: whole numbers below 9e15 exactly,
// others rounded to 6 significant digits, NaN and infinities as null. nlohmann-json prints a
// double with every digit it needs to round-trip (and "3.0" for three), which would change every
// figure spt prints; rounding here keeps the figures as they were, and this is the one place
// where spt's number form is decided. (Two forms differ from the printf("%.6g") of the writer
// this replaced, in value never: -0 is written 0, and a fraction of magnitude 999999.5 or more
// is written as the whole number it rounds to, 1234570 for 1.23457e+06.)
Doc number(double v);

// The text of `d`: compact (indent < 0) or one member a line, indented by `indent` spaces a
// level. Invalid UTF-8 in strings becomes U+FFFD (the output is always valid JSON); DEL and the
// C1 controls are escaped too, so nothing in it is acted on by a terminal that shows it.
std::string dump(const Doc& d, int indent = -1);

// The text of `d` with a layout between the two: a container for which `broken(node, key,
// depth)` is true has one element a line (indented two spaces for each broken container around
// it, its closing bracket on a line of its own even when empty); the others are written on one
// line with ", " and ": " between their parts. For files people read and diff, like the stroke
// list of spt export: one stroke a line.
std::string dump_layout(const Doc& d, const std::function<bool(const Doc& node, std::string_view key, int depth)>& broken);

}  // namespace spt::json
