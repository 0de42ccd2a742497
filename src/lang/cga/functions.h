// CGA's expression functions and shape attributes (seed 004 §III plus CityEngine's names, issue
// 4), with their arities: the checker (static checks) and the compiler both read this one table.
// These are not shape operations; those come from the shape registry (operations.h).
#pragma once

#include <cstdint>
#include <string_view>

namespace insula::lang::cga {

inline constexpr std::uint8_t kUnbounded = 255;

// Expression functions (lower-case, CityEngine's names).
struct FunctionInfo {
  std::string_view name;
  std::uint8_t min_args;
  std::uint8_t max_args;
  // letters as OperationInfo::signature (operations.h); `w` a word: a string, or a bare name
  // that is no attribute or constant (CityEngine's assetInfo(a, tx))
  std::string_view signature;
  std::string_view doc;
};

inline constexpr FunctionInfo kFunctions[] = {
    {"rand", 0, 2, "|n|nn", "uniform in [0,1), [0,a) or [a,b) from the shape's seeded generator"},
    {"rint", 1, 1, "n", "round to the nearest integer"},
    {"round", 1, 1, "n", "round half away from zero"},
    {"floor", 1, 1, "n", "largest integer <= x"},
    {"ceil", 1, 1, "n", "smallest integer >= x"},
    {"abs", 1, 1, "n", "absolute value"},
    {"min", 2, kUnbounded, "nn+", "smallest argument"},
    {"max", 2, kUnbounded, "nn+", "largest argument"},
    {"clamp", 3, 3, "nnn", "clamp(x, lo, hi)"},
    {"sqrt", 1, 1, "n", "square root"},
    {"pow", 2, 2, "nn", "x to the power y"},
    {"exp", 1, 1, "n", "e to the power x"},
    {"ln", 1, 1, "n", "natural logarithm"},
    {"sin", 1, 1, "n", "sine (degrees, as CityEngine)"},
    {"cos", 1, 1, "n", "cosine (degrees)"},
    {"tan", 1, 1, "n", "tangent (degrees)"},
    {"asin", 1, 1, "n", "arc sine (degrees)"},
    {"acos", 1, 1, "n", "arc cosine (degrees)"},
    {"atan", 1, 1, "n", "arc tangent (degrees)"},
    {"atan2", 2, 2, "nn", "atan2(y, x) (degrees)"},
    {"p", 1, 1, "n", "true with probability x (the shape's seeded generator)"},
    {"float", 1, 1, "v", "number from a number, bool or numeric string"},
    {"str", 1, 1, "v", "text of a value"},
    {"bool", 1, 1, "v", "truth of a value"},
    {"len", 1, 1, "s", "length of a string"},
    // CityEngine's string and string-list functions (docs/cityengine-dialect.md §5); a list is
    // a string of items each ended by ';' ("a;b;c;").
    {"find", 2, 3, "ss|ssn", "index of the n-th (default 0th) occurrence of a text, -1 if none"},
    {"substring", 3, 3, "snn", "substring(s, begin, end): the characters begin .. end - 1"},
    {"count", 2, 2, "ss", "how often a text occurs in a string"},
    {"replace", 3, 3, "sss", "replace(s, old, new): every occurrence replaced"},
    {"getPrefix", 2, 2, "ss", "the text before the first occurrence of a match (all if none)"},
    {"getSuffix", 2, 2, "ss", "the text after the last occurrence of a match (all if none)"},
    {"fileName", 1, 1, "s", "a path's file name with its extension (\"a/b.obj\" -> \"b.obj\")"},
    {"fileBasename", 1, 1, "s", "a path's file name without its extension (\"b\")"},
    {"fileDirectory", 1, 1, "s", "a path's folder with its last slash (\"a/\")"},
    {"fileExtension", 1, 1, "s", "a path's extension with its dot (\".obj\"; \"\" if none)"},
    {"getRange", 3, 3, "sss",
     "the text between the first occurrence of a start and the next occurrence of an end "
     "(\"\" without the start; the rest without the end)"},
    {"colorRGBToHex", 3, 3, "nnn", "\"#rrggbb\" of red, green, blue in [0, 1]"},
    {"colorHSVToHex", 3, 3, "nnn", "\"#rrggbb\" of hue (degrees), saturation, value in [0, 1]"},
    {"colorRamp", 2, 2, "sn",
     "\"#rrggbb\" at a value in [0, 1] of a ramp: whiteToBlack, greenToRed, yellowToRed, "
     "redToBlue, orangeToBlue, brownToBlue or spectrum"},
    {"colorHexToR", 1, 1, "s", "red of a \"#rrggbb\" colour, in [0, 1]"},
    {"colorHexToG", 1, 1, "s", "green of a \"#rrggbb\" colour, in [0, 1]"},
    {"colorHexToB", 1, 1, "s", "blue of a \"#rrggbb\" colour, in [0, 1]"},
    {"colorHexToO", 1, 1, "s", "opacity of a \"#rrggbb[aa]\" colour, in [0, 1]"},
    {"colorHexToH", 1, 1, "s", "hue of a \"#rrggbb\" colour, degrees in [0, 360)"},
    {"colorHexToS", 1, 1, "s", "saturation of a \"#rrggbb\" colour, in [0, 1]"},
    {"colorHexToV", 1, 1, "s", "value (brightness) of a \"#rrggbb\" colour, in [0, 1]"},
    {"listSize", 1, 1, "s", "number of items of a list"},
    {"listItem", 2, 2, "sn", "item i (0-based) of a list, \"\" past the end"},
    {"listFirst", 1, 1, "s", "first item of a list"},
    {"listLast", 1, 1, "s", "last item of a list"},
    {"listRange", 3, 3, "snn", "listRange(l, begin, end): items begin .. end - 1 as a list"},
    {"listIndex", 2, 2, "ss", "index of the first item equal to a text, -1 if none"},
    {"listCount", 2, 2, "ss", "how many items equal a text"},
    {"listAdd", 2, 2, "ss", "the list with an item appended"},
    {"listRemove", 2, 2, "ss", "the list without the items equal to a text"},
    {"listRandom", 1, 1, "s", "an item of a list drawn from the shape's seeded generator"},
    {"log10", 1, 1, "n", "logarithm to base 10"},
    {"isnan", 1, 1, "n", "whether x is not a number"},
    {"isinf", 1, 1, "n", "whether x is infinite"},
    // CityEngine's file functions (docs/assets.md), answered by the app's asset search.
    {"fileExists", 1, 1, "s", "whether the file exists (asset search order)"},
    {"fileSearch", 1, 1, "s", "the matching files of the workspace as a list"},
    {"fileRandom", 1, 1, "s", "one matching file, drawn from the shape's seeded generator"},
    {"assetInfo", 2, 2, "sw", "size (sx sy sz) or lowest corner (tx ty tz) of an asset"},
    {"imageInfo", 2, 2, "sw", "width (sx) or height (sy) of an image in pixels"},
    {"imageBestRatio", 2, 2, "sw",
     "of the images a search finds, the one whose width / height is nearest the scope's along "
     "two axes (\"xy\", \"yx\", \"xz\", ...); \"\" when none"},
    {"imagesSortRatio", 2, 2, "sw",
     "a string list of images sorted by how near their width / height is the scope's along two "
     "axes (nearest first)"},
    {"assetsSortSize", 3, 3, "vwn",
     "a string list (or string[]) of assets sorted by how near their size is the scope's along "
     "the axes (\"x\" .. \"xyz\"; nearest first); a maxScaleError > 0 keeps only those within "
     "that scaling (0.1: +-10%)"},
    {"assetsSortRatio", 2, 2, "vw",
     "a string list (or string[]) of assets sorted by how near their proportions are the scope's "
     "along the axes (\"xy\", \"xz\", \"yz\", \"xyz\"; nearest first)"},
    {"assetBestSize", 2, 2, "sw",
     "of the assets a search finds, the one whose size is nearest the scope's along the axes; "
     "\"\" when none"},
    {"assetBestRatio", 2, 2, "sw",
     "of the assets a search finds, the one whose proportions are nearest the scope's along the "
     "axes; \"\" when none"},
    {"assetApproxSize", 3, 3, "swn",
     "one of the n assets a search finds nearest the scope's size, drawn from the shape's seeded "
     "generator"},
    {"assetApproxRatio", 3, 3, "swn",
     "one of the n assets a search finds nearest the scope's proportions, drawn from the shape's "
     "seeded generator"},
    {"assetFitSize", 3, 3, "swn",
     "one of the assets a search finds that fit the scope's size within maxScaleError (0: any), "
     "drawn from the shape's seeded generator; \"\" when none"},
    // CityEngine's arrays (float[], bool[], string[]; docs/cga-cityengine.md, "Arrays").
    {"size", 1, 1, "v", "number of elements of an array"},
    {"nRows", 1, 1, "v", "number of rows of an array"},
    {"nColumns", 1, 1, "v", "number of columns of an array"},
    {"findFirst", 2, 3, "vv|vvn",
     "index of the first element equal to a value (within epsilon), -1 if none; in a string, "
     "the first position of a text"},
    {"findLast", 2, 3, "vv|vvn", "as findFirst, the last one"},
    {"sortIndices", 1, 1, "v", "per row, the indices of the elements in ascending order"},
    {"transpose", 1, 1, "v", "rows as columns"},
    {"floatArray", 0, 1, "|v", "an array converted to numbers (an empty one without argument)"},
    {"boolArray", 0, 1, "|v", "an array converted to booleans (an empty one without argument)"},
    {"stringArray", 0, 1, "|v", "an array converted to texts (an empty one without argument)"},
    {"listToArray", 1, 1, "s", "the items of a string list as a string[]"},
    {"listFromArray", 1, 1, "v", "an array as a string list"},
    {"readStringTable", 1, 1, "s", "a CSV file (asset search) as a 2-D string[]"},
    {"readFloatTable", 1, 1, "s", "a CSV file as a 2-D float[] (NaN where a cell is no number)"},
    {"print", 1, 1, "v", "prints the value to stderr, as the print operation does, and returns it"},
    {"listTerminate", 1, 1, "s", "a string list ended by ';' (unchanged if it is, or empty)"},
    {"getGeoCoord", 1, 1, "w",
     "the scope origin's x or y in the scene CRS, or its lon or lat (WGS 84 degrees)"},
};

// Shape attributes: `Shape.sx`, `Scope.sx` (the paper writes Shape., CityEngine scope.; both
// spellings, either case of the object name). Shape.occ("all") is a call.
struct AttributeInfo {
  std::string_view name;  // the member after "Shape." / "Scope."
  std::uint8_t args;      // 0 for a value, > 0 for a member call
  std::string_view doc;
};

inline constexpr AttributeInfo kShapeAttributes[] = {
    {"sx", 0, "scope size along x (meters)"},
    {"sy", 0, "scope size along y"},
    {"sz", 0, "scope size along z"},
    {"tx", 0, "scope origin x in the lot's frame"},
    {"ty", 0, "scope origin y in the lot's frame"},
    {"tz", 0, "scope origin z in the lot's frame"},
    {"elevation", 0, "height of the scope origin above the lot (CityEngine's scope.elevation)"},
    {"area", 0, "area of a flat shape's outline (sx * sy for a box scope)"},
    {"volume", 0, "sx * sy * sz"},
    {"depth", 0, "derivation depth of the shape"},
    {"index", 0, "index of the shape among its parent's children (split.index)"},
    {"total", 0, "number of children of the parent operation (split.total)"},
    {"sel", 0, "selector of the comp branch the shape came from (\"front\", \"side\"; comp.sel)"},
    {"occ", 1, "occlusion: \"none\", \"part\" or \"full\"; argument \"all\" (shapes of the lot)"},
};

// Object names whose members are shape attributes.
inline constexpr std::string_view kShapeObjects[] = {"Shape", "shape", "Scope",
                                                     "scope", "split", "comp"};

constexpr const FunctionInfo* find_function(std::string_view name) {
  for (const FunctionInfo& fn : kFunctions) {
    if (fn.name == name) return &fn;
  }
  return nullptr;
}

constexpr bool is_shape_object(std::string_view object) {
  for (std::string_view o : kShapeObjects) {
    if (o == object) return true;
  }
  return false;
}

// `object.member` (object one of kShapeObjects), e.g. ("Scope", "sx").
constexpr const AttributeInfo* find_shape_attribute(std::string_view object,
                                                    std::string_view member) {
  if (!is_shape_object(object)) return nullptr;
  for (const AttributeInfo& a : kShapeAttributes) {
    if (a.name == member) return &a;
  }
  return nullptr;
}

// Whether `count` arguments fit one alternative of `signature` (operations.h describes the
// letters, '+', '*' and '|').
constexpr bool signature_accepts(std::string_view signature, std::size_t count) {
  std::size_t begin = 0;
  while (true) {
    std::size_t end = signature.find('|', begin);
    if (end == std::string_view::npos) end = signature.size();
    std::size_t fixed = 0;
    bool unbounded = false;
    for (std::size_t i = begin; i < end; ++i) {
      const char c = signature[i];
      if (c == '+') {
        unbounded = true;
      } else if (c == '*') {
        unbounded = true;
        --fixed;  // the letter before '*' is optional
      } else {
        ++fixed;
      }
    }
    if (count == fixed || (unbounded && count >= fixed)) return true;
    if (end == signature.size()) return false;
    begin = end + 1;
  }
}

// The expected letter of argument `index` given `count` arguments (first matching
// alternative), or '\0' when no alternative accepts `count`.
constexpr char signature_letter(std::string_view signature, std::size_t count, std::size_t index) {
  std::size_t begin = 0;
  while (true) {
    std::size_t end = signature.find('|', begin);
    if (end == std::string_view::npos) end = signature.size();
    std::string_view alt = signature.substr(begin, end - begin);
    if (signature_accepts(alt, count)) {
      std::size_t pos = 0;
      char last = '\0';
      for (std::size_t i = 0; i < alt.size(); ++i) {
        const char c = alt[i];
        if (c == '+' || c == '*') continue;
        last = c;
        if (pos == index) return c;
        ++pos;
      }
      return last;  // inside the repeated tail
    }
    if (end == signature.size()) return '\0';
    begin = end + 1;
  }
}

// The self-checks of these lookups live in tests/lang/cga/operations_test.cc, not in static_asserts
// here: GCC with -fsanitize=undefined does not treat the loops over the tables as constant
// expressions, so a static_assert in this header broke every sanitizer build (INSULA_SANITIZE).

}  // namespace insula::lang::cga
