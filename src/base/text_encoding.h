// Text files as they are found (issue 20, item 5): rule files written on Windows are often
// Windows-1252, not UTF-8 (asset names with umlauts), some start with a byte order mark.
#pragma once

#include <string>
#include <string_view>

namespace insula::base {

// Whether `bytes` is well-formed UTF-8 (no overlong forms, no surrogates, at most U+10FFFF).
bool is_utf8(std::string_view bytes);

// `bytes` as UTF-8 without a leading byte order mark: unchanged when it is UTF-8, otherwise read
// as Windows-1252 (every byte is a character there; the five unassigned ones map to the C1
// controls of the same number, as the WHATWG encoding standard does). `converted` says which.
std::string utf8_text(std::string_view bytes, bool& converted);

}  // namespace insula::base
