// The model-to-text transformation of seed 004 §VII.C: a CGA grammar as the BuildingGen XML that
// the paper's target engine reads (Fig. 16, Fig. 17's Xpand template), after the check rules of
// Fig. 15. Format (docs/cga-model.md has the full description):
//
//   <BuildingGen>
//     <Rules priority="1">                      priority only when the source says `PRIORITY n:`
//       <Balcony_1>                             one element per predecessor symbol
//         <R11 condition="Shape.sx > 2">        one per production rule, R + rule id
//           <Fixed probability="0.5">          basic split (BS/Subdiv); Repeat: RR/Repeat;
//             <xProportions xr1="1.0" xr2="5.0" xr3="1.0"/>      Substitute: symbol lists
//             <yProportions/>                   sizes: "2.0" absolute, "1r" relative
//             <Elements><Wall/><Balcony_Center/><Wall/></Elements>
//           </Fixed>
//         </R11>
//       </Balcony_1>
//     </Rules>
//     <Terminals><Wall/><predefined-shape file="door.obj"/></Terminals>
//   </BuildingGen>
//
// Rules are grouped by predecessor (Fig. 16), in order of each predecessor's first rule.
#pragma once

#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

// Fig. 15: "The default Facade object is not defined!" -- the engine starts from this shape.
inline constexpr const char* kBuildingGenStartSymbol = "Facade";

// The Fig. 15 check rules and the limits of the target engine (§VII.C: "ComponentSplitRule and
// ScopeRules are not supported"), each violation an error at the offending rule or token:
//   CGA501 an empty shape with a scope (ε after a scope rule in the same successor)
//   CGA502 no shape with the symbol `Facade`
//   CGA503 a scope rule (T, S, Rx/Ry/Rz, I, [ and ])
//   CGA504 more than one priority set
//   CGA505 a rule without a predecessor
//   CGA506 a component split (CS, Comp, comp)
//   CGA507 a construct the XML cannot express: attribute declarations, generic operations,
//          split axes other than "X" and "Y", sizes other than numbers and relative numbers,
//          keyed branches, repeat patterns, a branch that is not exactly one shape, a split or
//          repeat mixed with other successor items
//   CGA508 text XML 1.0 cannot carry (control bytes or invalid UTF-8 in a string)
// Empty when the grammar can be transformed.
std::vector<base::Diagnostic> check_buildinggen(const Grammar& grammar, const base::Source& source);

// The BuildingGen XML of `grammar` (UTF-8, ends with a newline), or the diagnostics of
// check_buildinggen when it finds any.
base::Result<std::string> buildinggen_xml(const Grammar& grammar, const base::Source& source);

}  // namespace insula::lang::cga
