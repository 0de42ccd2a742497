// The geometry builtins' shared helpers (internal to lang/plasm): argument checks for
// polyhedra, building polyhedron values through the budgets, and the tables of natives each
// geometry file contributes (geometry.cc, map.cc, complex_ops.cc, boolean.cc).
#pragma once

#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "kernel/hull_nd.h"
#include "lang/plasm/eval_context.h"
#include "lang/plasm/polyhedron.h"

namespace insula::lang::plasm {

using Args = std::span<const ValuePtr>;

// The polyhedron `v` is, or PSM402 naming `who`.
const PolyPtr& polyhedron(Context& c, const ValuePtr& v, std::string_view who, Range at);
// A polyhedron value, its cells charged to the memory budget and its nesting bounded (PSM413).
ValuePtr polyhedron_value(Context& c, PolyPtr p, Range at);
// A number or a sequence of numbers, as a vector.
std::vector<double> numbers(Context& c, const ValuePtr& v, std::string_view who, Range at);
// Coordinate indices as PLaSM writes them (1-based; one number or a sequence), checked to lie in
// 1 .. 64 and returned 0-based.
std::vector<int> axes(Context& c, const ValuePtr& v, std::string_view who, Range at);
// The face lattice of the convex hull of `points` (dim coordinates each) for `who`: PSM418 past
// kMaxHighHullPoints points in 5D and more, PSM414 when there is no hull; its faces are charged
// to the memory budget.
kernel::PolytopeNd hull(Context& c, std::span<const double> points, int dim, std::string_view who,
                        Range at);
// PSM416 when `flat` holds a boolean's result: `who` works on convex cells only.
void cells_only(Context& c, const FlatComplex& flat, std::string_view who, Range at);
// A natural number checked to be at most `limit`.
std::size_t count_arg(Context& c, const ValuePtr& v, std::size_t limit, std::string_view who,
                      Range at);

// When `f` is a transformation T:axes:values, S:axes:values or R:axes:angle with every argument
// but the polyhedron, the map it stands for (STRUCT composes these without applying them).
bool as_affine(Context& c, const Function& f, Affine& out, Range at);
// The same for AFFINE:<<p0, ...>, <q0, ...>> (place.cc).
bool affine_from_points(Context& c, const Function& f, Affine& out, Range at);

// `a op b` where a polyhedron is involved: * is the Cartesian product (complex_ops.cc), + the
// union and - the difference (boolean.cc).
ValuePtr polyhedron_binary(Context& c, Op op, const ValuePtr& a, const ValuePtr& b, Range at);
ValuePtr product(Context& c, const PolyPtr& p, const PolyPtr& q, Range at);

// A map of points (the in point has the domain's coordinates, out receives out_dim).
using PointMap = std::function<void(const double* in, double* out)>;
// The cells of `domain` decomposed into simplices (one pulling triangulation in a global vertex
// order, so shared faces split alike) and sent through `f`; simplices the map collapses are
// dropped (map.cc).
PolyPtr map_complex(Context& c, const FlatComplex& domain, int out_dim, const PointMap& f,
                    std::string_view who, Range at);

std::span<const Native> geometry_natives();  // geometry.cc
std::span<const Native> map_natives();       // map.cc
std::span<const Native> complex_natives();   // complex_ops.cc
std::span<const Native> boolean_natives();   // boolean.cc
std::span<const Native> place_natives();     // place.cc

}  // namespace insula::lang::plasm
