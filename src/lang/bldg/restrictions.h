// Restriction rules (seed 000, §3.3, Table 3): the tunables of the floor-plan engine and the 3D
// builder, in their own `.rules` file of `key = value` lines. Keys, defaults and ranges are in
// docs/bldg-language.md and in the table of restrictions.cc.
#pragma once

#include <string>

#include "base/diagnostic.h"
#include "lang/bldg/model.h"

namespace insula::lang::bldg {

// Every key not in the file keeps its default (model.h). Unknown keys (BLD301), values of the
// wrong kind (BLD302), out of range (BLD303), keys given twice (BLD304) and inconsistent values
// (BLD305: door or window above the storey) are errors at the offending token, all reported.
// Never throws, never prints; any byte sequence is accepted.
base::Result<Restrictions> parse_restrictions(const base::Source& source);

// The rules as a `.rules` text that parse_restrictions reads back to the same values (every
// key, colours last in the order given).
std::string print_restrictions(const Restrictions& restrictions);

}  // namespace insula::lang::bldg
