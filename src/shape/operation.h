// The operation registry (design.md, "Operation registry"): every shape operation declares its
// name, typed parameters with defaults and a one-line doc, so argument checking, error text, the
// Lua and graph bindings and the reference page (docs/operations.md) are all driven from one table,
// in the manner of shapeml's operation table (style.md). Front-ends bind their arguments with
// bind() and run the operation with run(); the error texts are generic and come from the
// declarations.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "kernel/mesh.h"
#include "shape/shape_tree.h"

namespace insula::shape {

// A split size (CGA, seed 004 "Basic Split Rule"): absolute meters, relative (CGA 'r: a fraction of
// the scope size) or floating (CGA ~: a weight that absorbs what is left).
enum class SizeMode : std::uint8_t { kAbsolute, kRelative, kFloating };
struct SizeSpec {
  double value = 0;
  SizeMode mode = SizeMode::kAbsolute;
  friend bool operator==(const SizeSpec&, const SizeSpec&) = default;
};
// "2", "'0.5", "~1".
std::string to_string(const SizeSpec& size);
// The inverse: "2" (meters), "'0.5" (relative), "~1" (floating); nullopt for other text or a
// non-finite number.
std::optional<SizeSpec> parse_size(std::string_view text);

enum class ParamType : std::uint8_t {
  kNumber,    // double
  kInteger,   // std::int64_t
  kString,    // std::string
  kBool,      // bool
  kEnum,      // std::string, one of the declared choices
  kSize,      // SizeSpec
  kSizeList,  // std::vector<SizeSpec>
};
std::string_view param_type_name(ParamType type);

using ArgValue =
    std::variant<double, std::int64_t, std::string, bool, SizeSpec, std::vector<SizeSpec>>;
// How a value is written in the docs and error messages: "2", "'0.5", "x", "[2, ~1]".
std::string to_string(const ArgValue& value);

// A kEnum choice that stands for any whole number >= 0, bound as its decimal text (CityEngine's
// alignScopeToGeometry takes a face index or a selector word in one argument).
inline constexpr std::string_view kIndexChoice = "N";

struct ParamDecl {
  std::string name;
  ParamType type = ParamType::kNumber;
  std::string doc;
  std::optional<ArgValue> default_value;  // none: the parameter is required
  std::vector<std::string> choices;       // kEnum only
  // Inclusive bounds for kNumber and kInteger (and every entry of kSize/kSizeList values).
  std::optional<double> min;
  std::optional<double> max;
};

// Bound arguments: one value per declared parameter, defaults filled in, types exact.
class Arguments {
 public:
  void set(std::string name, ArgValue value) { values_[std::move(name)] = std::move(value); }
  bool has(std::string_view name) const { return values_.find(name) != values_.end(); }
  const ArgValue* get(std::string_view name) const;
  // Typed access; the binder guarantees the type, so a wrong name or type is a programming error
  // and returns a zero value.
  double number(std::string_view name) const;
  std::int64_t integer(std::string_view name) const;
  const std::string& string(std::string_view name) const;
  bool boolean(std::string_view name) const;
  SizeSpec size(std::string_view name) const;
  const std::vector<SizeSpec>& sizes(std::string_view name) const;

 private:
  std::map<std::string, ArgValue, std::less<>> values_;
};

// An asset (OBJ mesh) looked up by name; the app plugs in io's OBJ reader (the shape layer reads
// no files).
class AssetProvider {
 public:
  virtual ~AssetProvider() = default;
  // The mesh of asset `name`, or null with `error` set (e.g. "cannot open 'door.obj'").
  virtual std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                                   std::string& error) const = 0;
};

struct Context {
  const AssetProvider* assets = nullptr;
  // CityEngine's object frame (the initial shape's scope) for operations that take a frame; null:
  // the scope of the tree's root. A front-end that runs operations in a tree of its own (CGA's
  // derivation) passes the lot's scope here.
  const Scope* object = nullptr;
};

// An operation's outcome: the shapes it created (in a documented order), or an error message.
// `pieces[i]` says which declared piece child i is (the size entry of a split, the face index of
// a comp, 0 inside / 1 border for offset, ...) so a front-end can map children to successors even
// when an operation skips empty pieces.
struct OpResult {
  std::vector<ShapeId> children;
  std::vector<std::uint32_t> pieces;
  std::string error;
  std::string warning;  // set when the operation did something other than asked (a fallback)
  bool ok() const { return error.empty(); }
  void add(ShapeId child, std::uint32_t piece) {
    children.push_back(child);
    pieces.push_back(piece);
  }
  static OpResult failure(std::string message) {
    OpResult r;
    r.error = std::move(message);
    return r;
  }
};

using ExecuteFn = std::function<OpResult(ShapeTree&, ShapeId, const Arguments&, const Context&)>;

struct Operation {
  std::string name;
  std::string doc;  // one line
  std::vector<ParamDecl> params;
  ExecuteFn execute;
  // Inherited attributes the operation reads from the shape and sets on its children (texture
  // projections, uv sets, the colour map): a front-end that keeps attributes in a store of its
  // own (CGA's derivation) passes these in and takes the children's values back.
  std::vector<std::string> state{};
  const ParamDecl* param(std::string_view name) const;
};

// An argument as a front-end parsed it: named or positional (empty name), loosely typed: integers
// become numbers and sizes where needed, numbers become integers when integral, strings become
// enum values when allowed.
struct ArgInput {
  std::string name;
  ArgValue value;
};

struct BindResult {
  Arguments arguments;
  std::string error;  // empty on success
  bool ok() const { return error.empty(); }
};

class Registry {
 public:
  explicit Registry(std::vector<Operation> operations);

  const Operation* find(std::string_view name) const;
  std::span<const Operation> operations() const { return operations_; }

  // Checks `inputs` against the declaration: positional arguments in declaration order, then named
  // ones; errors (exact texts in docs/operations.md): unknown parameter, too many arguments, given
  // twice, wrong type, value not allowed, out of range, missing required.
  static BindResult bind(const Operation& op, const std::vector<ArgInput>& inputs);
  // bind() then execute on `shape`; "unknown operation 'x'" for a name not in the table. A failed
  // operation leaves the tree unchanged.
  OpResult run(ShapeTree& tree, ShapeId shape, std::string_view name,
               const std::vector<ArgInput>& inputs, const Context& context = {}) const;

 private:
  std::vector<Operation> operations_;  // sorted by name
};

// The table of every shape operation, built once on first use (immutable afterwards).
const Registry& registry();

// Lets a program amend the table before registry() first builds it: add operations or parameters
// of its own (a test binary proving that a new parameter reaches every front-end, a plugin).
// Returns false, and does nothing, once the table is built. Not thread-safe: call it during
// start-up (a static initialiser), before any front-end runs.
bool extend_registry(std::function<void(std::vector<Operation>&)> amend);

// The reference page docs/operations.md, generated from the registry.
std::string operations_reference_markdown();

// One front-end's spellings of an operation, for the reference page (empty: it has none). The
// shape layer knows no front-end; the program that writes the page passes them in.
struct FrontEndSpellings {
  std::string name;  // column title: "CGA", "Lua"
  std::function<std::vector<std::string>(const Operation&)> spell;
};
// The reference page with a table of every operation's spelling in each front-end.
std::string operations_reference_markdown(std::span<const FrontEndSpellings> front_ends);

}  // namespace insula::shape
