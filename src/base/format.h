// Text forms of values shared by every printer and dump (lang/cga printer and AST dump, lang/bldg
// printer): one spelling of numbers and string literals, so a value printed by one front-end reads
// back the same in the other and golden files do not drift apart.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace insula::base {

// The shortest decimal text that reads back as exactly `value` (std::to_chars round trip): 2.5,
// 0.1, 1e+300, -0. Callers that want -0 shown as 0 test for zero first.
std::string shortest_number(double value);

// `text` as a double-quoted literal: `"` and `\` are escaped with a backslash, newline and tab as
// \n and \t; every other byte is copied as is (the lexers' escape set, base/scanner.h).
std::string quoted_string(std::string_view text);

// The Levenshtein distance between two texts (bytes), for "did you mean" suggestions (the CLI's
// verbs, PLaSM's names).
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace insula::base
