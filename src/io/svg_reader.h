// SVG outlines (seed 002, §5: traced outlines of the site's spaces exported from a drawing program
// to SVG and imported as PLaSM polylines and polygons). Reads the geometry elements <polygon>,
// <polyline>, <line>, <rect>, <circle>, <ellipse> (32 segments) and <path> (M L H V Z A, absolute
// and relative; C S Q T curves flattened into 8 segments each, arcs into their share of 32), with
// the `transform` attributes of the element and of its enclosing groups (matrix, translate,
// scale, rotate, skewX, skewY). Coordinates stay in SVG user units with y pointing down, as
// written; the caller scales and flips. Diagnostics are `file:line:col` with codes SVG001..
// (docs/formats.md); bad input never crashes.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/vec.h"

namespace insula::io {

struct SvgOutline {
  std::string id;  // the element's id attribute, or "<tag>#<n>" (n counts from 1 in the file)
  std::vector<kernel::Vec2> points;
  bool closed = false;  // polygon, rect, or a path subpath ended by Z
};

// Every outline of the document in document order (a path gives one outline per subpath). Fails
// on malformed XML, a root that is not <svg>, malformed numbers or path data, or no outline.
base::Result<std::vector<SvgOutline>> read_svg(std::string_view text,
                                               const std::string& source_name);

}  // namespace insula::io
