// The CGA AST as XMI 2.0, an instance of the Ecore metamodel docs/cga.ecore (seed 004 §IV:
// "The complete diagram of the ECore meta-model"), so EMF tools open the model. Containment
// features are child elements named after the feature, subclasses carry xsi:type="cga:Class",
// attributes are XML attributes; every Located element has line/column/endLine/endColumn.
#pragma once

#include <string>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

// nsURI and nsPrefix of docs/cga.ecore.
inline constexpr const char* kCgaNsUri = "http://insula.dev/cga/1.0";
inline constexpr const char* kCgaNsPrefix = "cga";

// The XMI document of `grammar` parsed from `source`, UTF-8, ending with a newline. Text that
// XML cannot carry (control bytes, invalid UTF-8 inside CGA strings) is replaced by U+FFFD.
std::string model_xmi(const Grammar& grammar, const base::Source& source);

}  // namespace insula::lang::cga
