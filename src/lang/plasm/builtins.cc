#include "lang/plasm/builtins.h"

#include <algorithm>
#include <array>
#include <string>

namespace insula::lang::plasm {
namespace {

// Sorted by name (find_builtin searches it by bisection; a test keeps it sorted).
constexpr std::array kBuiltins = {
    Builtin{"AA", kAnyArity, "AA:f:<x1, ..., xn> is <f:x1, ..., f:xn> (apply to all)"},
    Builtin{"ABS", kAnyArity, "absolute value"},
    Builtin{"ACOS", kAnyArity, "arc cosine"},
    Builtin{"AFFINE", kAnyArity,
            "AFFINE:<<p0, ..., pd>, <q0, ..., qd>>:p, the affine map sending each p_i to q_i "
            "(local to global coordinates by 4 points)"},
    Builtin{"AL", 2, "AL:<x, <y, ...>> is <x, y, ...> (append left)"},
    Builtin{
        "ALIGN", kAnyArity,
        "ALIGN:<<axis, f, g>, ...>:<p, q> is STRUCT:<p, q'>, q translated along each axis so that "
        "g:axis:q' meets f:axis:p (f, g: MIN, MED, MAX)"},
    Builtin{"AND", kAnyArity, "true when every element of a sequence is true"},
    Builtin{"AR", 2, "AR:<<x, ...>, y> is <x, ..., y> (append right)"},
    Builtin{"ASIN", kAnyArity, "arc sine"},
    Builtin{"ATAN", kAnyArity, "arc tangent"},
    Builtin{"ATAN2", 2, "ATAN2:<y, x>, the angle of the point (x, y)"},
    Builtin{"BEZIER", kAnyArity,
            "BEZIER:Sk:<p0, ..., pn>, the coordinate functions of a Bezier map in parameter k; "
            "control points may be functions (transfinite)"},
    Builtin{"BOTTOM", 2, "p BOTTOM q puts q under p (its top on p's bottom), centred in x and y"},
    Builtin{"BUTLAST", kAnyArity, "a sequence without its last element"},
    Builtin{"C", kAnyArity, "C:f:x:y is f:<x, y> (curry)"},
    Builtin{"CAT", kAnyArity, "concatenation of a sequence of sequences"},
    Builtin{"CIRCLE", kAnyArity,
            "CIRCLE:r:<n, m>, the disk of radius r in the xy plane, n sectors and m rings of "
            "triangles (the collapsed ones at the centre dropped)"},
    Builtin{"COMP", kAnyArity, "COMP:<f, g, ...> is f ~ g ~ ..."},
    Builtin{"CONS", kAnyArity, "CONS:<f1, ..., fn>:x is <f1:x, ..., fn:x>, as [f1, ..., fn]"},
    Builtin{"COS", kAnyArity, "cosine"},
    Builtin{"CUBOID", kAnyArity,
            "CUBOID:<a, b, ...>, the box [0, a] x [0, b] x ... (one convex cell)"},
    Builtin{"CYLINDER", 2,
            "CYLINDER:<r, h>:n, a solid prism of height h over the regular n-gon inscribed in "
            "the circle of radius r (one convex cell)"},
    Builtin{"DIFFERENCE", kAnyArity,
            "DIFFERENCE:<p, q, ...>, p minus the others (as -): a closed 3D solid"},
    Builtin{"DISTL", 2, "DISTL:<x, <y1, ..., yn>> is <<x, y1>, ..., <x, yn>>"},
    Builtin{"DISTR", 2, "DISTR:<<x1, ..., xn>, y> is <<x1, y>, ..., <xn, y>>"},
    Builtin{"EMBED", kAnyArity, "EMBED:n:p gives p n more coordinates, all zero"},
    Builtin{"EQ", kAnyArity, "true when the elements of a sequence are equal"},
    Builtin{"EXP", kAnyArity, "exponential"},
    Builtin{"FALSE", kAnyArity, "the false value"},
    Builtin{"FIRST", kAnyArity, "the first element of a sequence"},
    Builtin{"FROMTO", 2, "FROMTO:<a, b> is <a, a+1, ..., b>, as a .. b"},
    Builtin{"GE", kAnyArity, "GE:a:x is x >= a"},
    Builtin{"GT", kAnyArity, "GT:a:x is x > a"},
    Builtin{"ID", kAnyArity, "the identity function"},
    Builtin{"INSL", kAnyArity, "INSL:f:<x1, ..., xn>, f inserted from the left"},
    Builtin{"INSR", kAnyArity, "INSR:f:<x1, ..., xn>, f inserted from the right"},
    Builtin{"INTERSECTION", kAnyArity,
            "INTERSECTION:<p, q, ...>, the common part of 3D solids: a closed 3D solid"},
    Builtin{"INTERVALS", kAnyArity, "INTERVALS:a:n, [0, a] split into n equal 1D cells"},
    Builtin{"INTSTO", kAnyArity, "INTSTO:n is <1, 2, ..., n>"},
    Builtin{"ISBOOL", kAnyArity, "predicate: a truth value"},
    Builtin{"ISFUN", kAnyArity, "predicate: a function"},
    Builtin{"ISINT", kAnyArity, "predicate: an integer"},
    Builtin{"ISINTPOS", kAnyArity, "predicate: an integer > 0"},
    Builtin{"ISNAT", kAnyArity, "predicate: an integer >= 0"},
    Builtin{"ISNUM", kAnyArity, "predicate: a number"},
    Builtin{"ISPOL", kAnyArity, "predicate: a polyhedral complex"},
    Builtin{"ISREAL", kAnyArity, "predicate: a number"},
    Builtin{"ISREALPOS", kAnyArity, "predicate: a number > 0"},
    Builtin{"ISSEQ", kAnyArity, "predicate: a sequence"},
    Builtin{"ISSEQOF", kAnyArity,
            "ISSEQOF:pred, predicate: a sequence whose elements satisfy pred"},
    Builtin{"ISSTRING", kAnyArity, "predicate: a string"},
    Builtin{"JOIN", kAnyArity,
            "JOIN:p or JOIN:<p, q, ...>, the convex hull of all their points (one cell)"},
    Builtin{"K", kAnyArity, "K:x:y is x (the constant function of x)"},
    Builtin{"LAST", kAnyArity, "the last element of a sequence"},
    Builtin{"LE", kAnyArity, "LE:a:x is x <= a"},
    Builtin{"LEFT", 2, "p LEFT q puts q left of p along x, bottoms aligned"},
    Builtin{"LEN", kAnyArity, "the length of a sequence"},
    Builtin{"LIST", kAnyArity, "LIST:x is <x>"},
    Builtin{"LN", kAnyArity, "natural logarithm"},
    Builtin{"LT", kAnyArity, "LT:a:x is x < a"},
    Builtin{"MAP", kAnyArity,
            "MAP:<f1, ..., fn>:domain (or MAP:f, f giving a point), a simplicial decomposition of "
            "the domain through the coordinate functions; collapsed simplices are dropped"},
    Builtin{"MAX", kAnyArity, "MAX:k:p, the greatest coordinate k of p (k a sequence: a sequence)"},
    Builtin{"MED", kAnyArity,
            "MED:k:p, the middle of p along coordinate k (k a sequence: a sequence)"},
    Builtin{"MIN", kAnyArity, "MIN:k:p, the least coordinate k of p (k a sequence: a sequence)"},
    Builtin{"MKPOL", 3,
            "MKPOL:<verts, cells, pols>, a complex from its vertices, its convex cells (lists of "
            "1-based vertex indices) and the cells pols keeps"},
    Builtin{"NOT", kAnyArity, "logical negation"},
    Builtin{"OFFSET", kAnyArity,
            "OFFSET:<d1, ..., dn>:p, each cell of p swept by the box [0, d1] x ... x [0, dn] "
            "(a Minkowski sum, cell by cell)"},
    Builtin{"OR", kAnyArity, "true when some element of a sequence is true"},
    Builtin{"PI", kAnyArity, "the number pi"},
    Builtin{"Q", kAnyArity, "Q:a, as QUOTE:<a>"},
    Builtin{"QUOTE", kAnyArity,
            "QUOTE:<a, -b, c>, consecutive 1D cells of lengths a and c with a gap b (negative: a "
            "gap)"},
    Builtin{"R", kAnyArity,
            "R:<i, j>:angle:p, p rotated by angle in the plane of coordinates i and j, from i "
            "towards j (in STRUCT: what follows)"},
    Builtin{"REPEAT", kAnyArity, "REPEAT:n:x is <x, ..., x> (n times), as #:n:x"},
    Builtin{"REVERSE", kAnyArity, "a sequence in reverse order"},
    Builtin{"RIGHT", 2, "p RIGHT q puts q right of p along x, bottoms aligned"},
    Builtin{"S", kAnyArity,
            "S:<i, ...>:<s, ...>:p, p scaled by s along coordinate i (in STRUCT: what follows)"},
    Builtin{"S1", kAnyArity, "the first element (selector)"},
    Builtin{"S2", kAnyArity, "the second element (selector)"},
    Builtin{"S3", kAnyArity, "the third element (selector)"},
    Builtin{"S4", kAnyArity, "the fourth element (selector)"},
    Builtin{"S5", kAnyArity, "the fifth element (selector)"},
    Builtin{"S6", kAnyArity, "the sixth element (selector)"},
    Builtin{"S7", kAnyArity, "the seventh element (selector)"},
    Builtin{"S8", kAnyArity, "the eighth element (selector)"},
    Builtin{"S9", kAnyArity, "the ninth element (selector)"},
    Builtin{"SEL", kAnyArity, "SEL:k, the selector of the k-th element"},
    Builtin{"SIMPLEX", kAnyArity,
            "SIMPLEX:d, the standard d-simplex (the origin and the d unit points)"},
    Builtin{"SIN", kAnyArity, "sine"},
    Builtin{"SIZE", kAnyArity,
            "SIZE:k:p, the extent of p along coordinate k (k a sequence: a sequence)"},
    Builtin{"SKELETON", kAnyArity,
            "SKELETON:k:p, the k-dimensional faces of the cells of p, each once"},
    Builtin{"SPHERE", kAnyArity,
            "SPHERE:r:<n, m>, the sphere surface of radius r at the origin, n bands from pole to "
            "pole and m sectors"},
    Builtin{"SPLITCELLS", kAnyArity, "the convex cells of a polyhedron, one polyhedron each"},
    Builtin{"SQRT", kAnyArity, "square root"},
    Builtin{"STRUCT", kAnyArity,
            "STRUCT:<p, T:..., q, ...>, an assembly; a transformation applies to what follows"},
    Builtin{"SVG", kAnyArity,
            "SVG:\"plan.svg\", a drawing's outlines as polyhedra of the plane (y up); "
            "SVG:\"plan.svg#id\" one of them"},
    Builtin{
        "T", kAnyArity,
        "T:<i, ...>:<d, ...>:p, p translated by d along coordinate i (in STRUCT: what follows)"},
    Builtin{"TAIL", kAnyArity, "a sequence without its first element"},
    Builtin{"TAN", kAnyArity, "tangent"},
    Builtin{"TOP", 2, "p TOP q puts q on top of p (its bottom on p's top), centred in x and y"},
    Builtin{"TORUS", 2,
            "TORUS:<r1, r2>:<n, m>, the surface of a tube of radius r1 around the circle of "
            "radius r2 in the xy plane, n sectors around the tube and m around z"},
    Builtin{"TRANS", kAnyArity, "the transpose of a sequence of sequences"},
    Builtin{"TRILINEAR", kAnyArity,
            "TRILINEAR:<q000, q100, ..., q111>:p maps p's bounding box onto the volume of those 8 "
            "corners"},
    Builtin{"TRUE", kAnyArity, "the true value"},
    Builtin{"TRUNCONE", 3,
            "TRUNCONE:<r1, r2, h>:n, the side surface of a truncated cone, radius r1 at z = 0 "
            "and r2 at z = h, n sectors"},
    Builtin{"TT", kAnyArity, "predicate: anything"},
    Builtin{"UNION", kAnyArity,
            "UNION:<p, q, ...>, the union of 3D solids (as +): one merged closed solid"},
    Builtin{"XOR", kAnyArity,
            "XOR:<p, q, ...>, what lies in an odd number of 3D solids: a closed 3D solid"},
};

}  // namespace

std::span<const Builtin> builtins() {
  return kBuiltins;
}

const Builtin* find_builtin(std::string_view key) {
  const auto it = std::lower_bound(kBuiltins.begin(), kBuiltins.end(), key,
                                   [](const Builtin& b, std::string_view k) { return b.name < k; });
  return it != kBuiltins.end() && it->name == key ? &*it : nullptr;
}

namespace {

// A table cell: `|` would end it.
std::string cell(std::string_view text) {
  std::string out;
  for (char ch : text) {
    if (ch == '|') out += '\\';
    out += ch;
  }
  return out;
}

}  // namespace

std::string library_reference_markdown() {
  std::string page =
      "# PLaSM library reference\n\n"
      "<!-- Generated from src/lang/plasm/builtins.cc by library_reference_markdown(); do not "
      "edit. Regenerate with INSULA_REGENERATE=1 ctest -R lang.plasm.library_doc_test. -->\n\n"
      "Every name a PLaSM program may use without defining it (docs/plasm-language.md): the FL "
      "toolbox and the geometry library of seed 002. Names are case-insensitive. *Takes* is the "
      "length of the sequence the builtin is applied to, where the checker verifies it "
      "(`TRUNCONE:<r1, "
      "r2, h>`); builtins applied to other arguments say so in their summary, curried left to "
      "right (`T:<1, 2>:<dx, dy>:p`).\n\n"
      "| Name | Takes | Summary |\n"
      "|---|---|---|\n";
  for (const Builtin& b : kBuiltins) {
    page += "| `";
    page += b.name;
    page += "` | ";
    page += b.arity == kAnyArity ? std::string("-") : "a sequence of " + std::to_string(b.arity);
    page += " | ";
    page += cell(b.summary);
    page += " |\n";
  }
  return page;
}

}  // namespace insula::lang::plasm
