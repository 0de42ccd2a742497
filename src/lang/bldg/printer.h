// Grammar printer: a Building model as .bldg text (seed 000, §3.1 rule format), so a generated
// building (§4.3) can be edited and rebuilt, and a parsed one written back in canonical form.
#pragma once

#include <string>

#include "lang/bldg/model.h"

namespace insula::lang::bldg {

// Canonical text: the axiom first, then every part, floor and division subtree depth first,
// then the transitions, one rule per line, numbers in shortest round-trip form. Symbols that are
// empty, not identifiers or repeated are replaced by fresh ones (transitions follow a renamed
// room). For a model that passes the moderator, parse_building(print_building(m)) gives m back
// (locations aside) and print_building is idempotent over parse.
std::string print_building(const Building& building);

// The spellings used by the grammar ("HipGlued", "horizontal", "big", "door").
const char* roof_name(RoofKind kind);
const char* orientation_name(Orientation orientation);
const char* size_name(SizeLabel size);
const char* transition_name(TransitionKind kind);

}  // namespace insula::lang::bldg
