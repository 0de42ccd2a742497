// Reads BuildingGen XML (buildinggen_xml.h, seed 004 §VII.C Fig. 16) back into a CGA grammar:
// the reverse of the model-to-text transformation, for `insula transform x.xml --to cga`.
// For every grammar that check_buildinggen accepts, read(buildinggen_xml(g)) printed and parsed
// again has the AST dump of g (source positions aside), provided the rules of each predecessor
// are adjacent in g (the XML groups rules by predecessor, Fig. 16).
#pragma once

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

// Parses `xml` (any bytes). On success the grammar has one priority set (explicit when <Rules>
// has a priority attribute) and all source ranges zero; print it with printer.h. Errors are
// `file:line:col: error[CGA52x]: ...` at the offending element or attribute:
//   CGA520 malformed XML             CGA526 a size that is not a number or `Nr`
//   CGA521 unexpected/missing element or text   CGA527 a bad condition or probability expression
//   CGA522 an element name that is not a CGA symbol  CGA528 a bad arrow or operation spelling
//   CGA523 a rule element not named R<id>  CGA529 a shape that is neither a rule nor a terminal
//   CGA524 an unknown attribute      CGA530 an unnamed rule with a condition or a `~>` first arrow
//   CGA525 bad proportions (both or neither axis, names not xr1..xrN, count mismatch)
base::Result<Grammar> read_buildinggen_xml(const base::Source& xml);

}  // namespace insula::lang::cga
