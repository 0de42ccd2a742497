// SVG writer (docs/formats.md, "SVG"): a plan seen from above, to scale. The viewBox is in meters
// with y flipped so north (+y of the CRS grid) is up; the drawing is shifted so its south-west
// corner sits at (0, 0) (browsers draw in float32, which would blur UTM-sized numbers). Each
// building's ground faces (else its downward-facing faces) are filled and outlined (edges shared by
// two ground pieces are not drawn) and labelled with its id at the footprint's pole of
// inaccessibility (the inside point farthest from the outline), plus a scale bar and a north arrow.
// With SvgOptions::section_height set, the cut lines of every face with that horizontal plane are
// drawn over the footprints (a storey plan). Labels are XML-escaped; output is deterministic.
//
// Floor plans: when a building carries shape::StoreyPlan (traversable buildings, seed 000) and no
// section is asked, the picture is the floor plans instead: one panel per storey level, side by
// side from the lowest level at the left (west), all at one scale, titled "storey <level>"
// (every building's plan of a level in the same panel). Each panel draws the rooms filled by type
// and labelled with name and area (m², one decimal), walls (exterior darker), windows (a blue
// double line), doors (the open leaf from the hinge and a dashed swing arc; entrances in red) and
// stairs (treads and an arrow pointing up the flight), plus one scale bar and north arrow.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "shape/scene.h"

namespace insula::io {

struct SvgOptions {
  // Size of the picture: pixels per meter; 0 fits the longer side of the picture in 1000 px.
  double pixels_per_meter = 0;
  // Local z (meters, the scene's Z-up frame) of a horizontal section; none draws footprints only.
  std::optional<double> section_height;
  bool labels = true;
};

// The SVG text of `scene`.
std::string svg_text(const shape::Scene& scene, const SvgOptions& options = {});

// Writes `path` atomically. Returns an empty string on success, else a message naming the file.
std::string write_svg(const shape::Scene& scene, const std::filesystem::path& path,
                      const SvgOptions& options = {});

// `text` safe inside XML character data and attribute values: & < > " ' escaped, control
// characters and invalid UTF-8 bytes replaced by '?'.
std::string xml_escape(std::string_view text);

}  // namespace insula::io
