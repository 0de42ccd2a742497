// Text that XML 1.0 can carry. CGA strings may hold any byte but `"` and a line break, while an
// XML document may only hold valid UTF-8 without most control characters (even escaped), so the
// XML writers check (BuildingGen, where the text must round-trip) or replace (XMI) such text.
#pragma once

#include <string>
#include <string_view>

namespace insula::lang::cga {

// Length (1 to 4) of the valid UTF-8 encoded scalar value at byte `i` of `text`, or 0 when the
// bytes there are not one (overlong forms, surrogates and values beyond U+10FFFF are invalid).
std::size_t utf8_length(std::string_view text, std::size_t i);

// True when `text` is valid UTF-8 of characters allowed in XML 1.0 (tab, LF, CR and from U+0020,
// without U+FFFE and U+FFFF).
bool is_xml_text(std::string_view text);

// `text` with every byte sequence that is_xml_text rejects replaced by U+FFFD.
std::string to_xml_text(std::string_view text);

}  // namespace insula::lang::cga
