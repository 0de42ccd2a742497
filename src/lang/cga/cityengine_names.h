// CityEngine's operations and functions that Insula does not run yet (issue 20 item 6:
// "unsupported is said, never skipped"). A name here is known to be CityEngine's, so the checker
// says "not supported" (CGA901 / CGA902) instead of "unknown". Operations whose loss only costs
// detail (labels, normals) are warnings (CGA903): the model is still made,
// without that detail. docs/cityengine-dialect.md keeps the coverage table.
#pragma once

#include <string_view>

namespace insula::lang::cga {

// Operations that change only what Insula does not model yet: skipped with warning CGA903.
inline constexpr std::string_view kDetailOperations[] = {
    "setNormals",     "softenNormals", "deleteHoles",
    "reduceGeometry", "setMaterial",   "resetMaterials",
    "resetGeometry",  "deleteTags",    "tag",
};

// Operations that change geometry and are not implemented: error CGA901.
inline constexpr std::string_view kUnsupportedOperations[] = {
    "mirrorScope",
    "roofRidge",
    "footprint",
    "modify",
    "taper",
    "polygon",
    "bulkhead",
    "extrudeAlongUV",
    "splitAndSetbackPerimeter",
    "setbackToArea",
    "setbackPerimeter",
    "fillHoles",
    "mergeVertices",
    "stop",
    "inline",
    "dim",
};

// Functions of CityEngine that Insula does not evaluate yet: error CGA902.
inline constexpr std::string_view kUnsupportedFunctions[] = {
    "filesSearch",    "contextCompare", "contextCount", "getObjectAttr", "readTextFile",
    "sortRowIndices", "setElems",       "isTagged",     "isNull",        "hash",
};

constexpr bool contains(const auto& table, std::string_view name) {
  for (std::string_view entry : table) {
    if (entry == name) return true;
  }
  return false;
}

}  // namespace insula::lang::cga
