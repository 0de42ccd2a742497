// Registry entries for the single-component operations of seed 001 (component_ops.h). The
// operations that take sets of components (booleans, joint extrusion, constraints) are called
// directly by the front-ends, since registry arguments are plain values.
#include "shape/component_ops.h"
#include "shape/query.h"

namespace insula::shape {

namespace {

ParamDecl number(std::string name, std::string doc, std::optional<double> value,
                 std::optional<double> min = {}) {
  ParamDecl p{std::move(name), ParamType::kNumber, std::move(doc), {}, {}, min, {}};
  if (value) p.default_value = ArgValue{*value};
  return p;
}

Axis axis_of(const std::string& s) {
  return s == "x" ? Axis::kX : s == "y" ? Axis::kY : Axis::kZ;
}

LeftOver policy_of(const std::string& s) {
  if (s == "last") return LeftOver::kLast;
  if (s == "both") return LeftOver::kBoth;
  if (s == "spread") return LeftOver::kSpread;
  return LeftOver::kFirst;
}

// Every component labelled "opening" (add_opening's label): the default for solid geometry.
std::vector<ShapeId> all_openings(const ShapeTree& tree) {
  std::vector<ShapeId> out;
  for (ShapeId id = 0; id < tree.size(); ++id) {
    if (tree.has_label(id, "opening")) out.push_back(id);
  }
  return out;
}

Operation slice_op() {
  return {"slice",
          "Slices along a scope axis into pieces of `size` meters; the left-over goes to the "
          "first, the last, both ends or is spread over every piece (seed 001 §3.4.3).",
          {{"axis", ParamType::kEnum, "scope axis", std::nullopt, {"x", "y", "z"}, {}, {}},
           number("size", "piece size (meters, > 0)", {}, 1e-9),
           {"leftover",
            ParamType::kEnum,
            "who gets the left-over space",
            ArgValue{std::string("first")},
            {"first", "last", "both", "spread"},
            {},
            {}}},
          [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
            return slice(t, id, axis_of(a.string("axis")), a.number("size"),
                         policy_of(a.string("leftover")));
          }};
}

Operation opening_op() {
  return {"opening",
          "Adds a door or window to a flat wall component: a box through the walls on both "
          "sides of the face, with frame and leaf geometry; solid geometry cuts it out (§4.4).",
          {{"kind",
            ParamType::kEnum,
            "door or window",
            ArgValue{std::string("door")},
            {"door", "window"},
            {},
            {}},
           number("u", "centre along the wall's x (meters)", {}),
           number("sill", "bottom above the face's y = 0 (meters)", 0.0),
           number("width", "meters", 0.9, 1e-3),
           number("height", "meters", 2.1, 1e-3),
           number("depth", "reach on each side of the face (meters)", 0.5, 1e-3),
           number("frame", "frame profile width (meters)", 0.05, 0.0)},
          [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
            OpeningSpec spec;
            spec.kind = a.string("kind") == "window" ? OpeningKind::kWindow : OpeningKind::kDoor;
            spec.u = a.number("u");
            spec.sill = a.number("sill");
            spec.width = a.number("width");
            spec.height = a.number("height");
            spec.depth = a.number("depth");
            spec.frame = a.number("frame");
            return add_opening(t, id, spec);
          }};
}

Operation solid_op() {
  return {"solid",
          "Solid geometry of the component's boundary with every opening that pierces it cut "
          "out, in a child labelled solid (seed 001 §3.6, §4.4).",
          {number("uv_scale", "meters per texture repeat (0: no texture coordinates)", 1.0, 0.0),
           {"material", ParamType::kString, "material name", ArgValue{std::string()}, {}, {}, {}}},
          [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
            SolidOptions options;
            options.openings = all_openings(t);
            options.uv_scale = a.number("uv_scale");
            options.material = a.string("material");
            return solid_geometry(t, id, options);
          }};
}

Operation instance_op() {
  return {"instance",
          "Creates a box child in the parent's scope space, clipped by the parent's boundary "
          "(seed 001 §3.4.3 Instancing); size z = 0 makes a flat child.",
          {number("x", "offset x (meters)", 0.0),
           number("y", "offset y (meters)", 0.0),
           number("z", "offset z (meters)", 0.0),
           number("sx", "size x (meters)", {}, 0.0),
           number("sy", "size y (meters)", {}, 0.0),
           number("sz", "size z (meters)", {}, 0.0),
           {"clip", ParamType::kBool, "clip by the parent's boundary", ArgValue{true}, {}, {}, {}}},
          [](ShapeTree& t, ShapeId id, const Arguments& a, const Context&) {
            return instance_box(t, id, {a.number("x"), a.number("y"), a.number("z")},
                                {a.number("sx"), a.number("sy"), a.number("sz")},
                                a.boolean("clip"));
          }};
}

}  // namespace

std::vector<Operation> component_operations() {
  std::vector<Operation> ops;
  ops.push_back(slice_op());
  ops.push_back(opening_op());
  ops.push_back(solid_op());
  ops.push_back(instance_op());
  return ops;
}

}  // namespace insula::shape
