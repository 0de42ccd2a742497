#include "shape/operation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>

#include "shape/building_ops.h"
#include "shape/component_ops.h"
#include "shape/ops.h"

namespace insula::shape {

namespace {

// Joins by append (GCC 12 warns falsely, -Wrestrict, on "x" + std::string chains).
std::string concat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out.append(p);
  return out;
}

std::string number_text(double value) {
  return to_string(Value{value});
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out.append(separator);
    out.append(items[i]);
  }
  return out;
}

// The article-less kind of a given value, for "got ..." in error messages.
std::string_view value_kind(const ArgValue& value) {
  switch (value.index()) {
    case 0:
      return "a number";
    case 1:
      return "an integer";
    case 2:
      return "a string";
    case 3:
      return "a bool";
    case 4:
      return "a size";
    default:
      return "a size list";
  }
}

std::string expected_kind(const ParamDecl& p) {
  switch (p.type) {
    case ParamType::kNumber:
      return "a number";
    case ParamType::kInteger:
      return "an integer";
    case ParamType::kString:
      return "a string";
    case ParamType::kBool:
      return "a bool";
    case ParamType::kEnum:
      return concat({"one of ", join(p.choices, ", ")});
    case ParamType::kSize:
      return "a size";
    case ParamType::kSizeList:
      return "a size list";
  }
  return {};
}

bool takes_index(const ParamDecl& p) {
  return std::find(p.choices.begin(), p.choices.end(), kIndexChoice) != p.choices.end();
}

bool is_index_text(std::string_view s) {
  return !s.empty() && s.size() < 16 &&
         std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Converts `value` to the parameter's type, or returns false.
bool coerce(const ParamDecl& p, const ArgValue& value, ArgValue& out) {
  const auto* d = std::get_if<double>(&value);
  const auto* i = std::get_if<std::int64_t>(&value);
  switch (p.type) {
    case ParamType::kNumber:
      if (i != nullptr) return out = static_cast<double>(*i), true;
      return d != nullptr && (out = *d, true);
    case ParamType::kInteger:
      if (d != nullptr && std::isfinite(*d) && *d == std::trunc(*d) && std::fabs(*d) < 9e15) {
        return out = static_cast<std::int64_t>(*d), true;
      }
      return i != nullptr && (out = *i, true);
    case ParamType::kEnum:
      if (takes_index(p)) {
        std::int64_t n = -1;
        if (i != nullptr) n = *i;
        if (d != nullptr && std::isfinite(*d) && *d == std::trunc(*d) && std::fabs(*d) < 9e15) {
          n = static_cast<std::int64_t>(*d);
        }
        if (n >= 0) return out = std::to_string(n), true;
      }
      return std::holds_alternative<std::string>(value) && (out = value, true);
    case ParamType::kString:
      return std::holds_alternative<std::string>(value) && (out = value, true);
    case ParamType::kBool:
      return std::holds_alternative<bool>(value) && (out = value, true);
    case ParamType::kSize:
      if (d != nullptr) return out = SizeSpec{*d, SizeMode::kAbsolute}, true;
      if (i != nullptr) return out = SizeSpec{static_cast<double>(*i), SizeMode::kAbsolute}, true;
      return std::holds_alternative<SizeSpec>(value) && (out = value, true);
    case ParamType::kSizeList: {
      ArgValue single;
      ParamDecl one = p;
      one.type = ParamType::kSize;
      if (coerce(one, value, single)) {
        return out = std::vector<SizeSpec>{std::get<SizeSpec>(single)}, true;
      }
      return std::holds_alternative<std::vector<SizeSpec>>(value) && (out = value, true);
    }
  }
  return false;
}

// The numbers a range check applies to.
std::vector<double> checked_numbers(const ArgValue& value) {
  if (const auto* d = std::get_if<double>(&value)) return {*d};
  if (const auto* i = std::get_if<std::int64_t>(&value)) return {static_cast<double>(*i)};
  if (const auto* s = std::get_if<SizeSpec>(&value)) return {s->value};
  if (const auto* l = std::get_if<std::vector<SizeSpec>>(&value)) {
    std::vector<double> out;
    for (const SizeSpec& s : *l) out.push_back(s.value);
    return out;
  }
  return {};
}

// Empty when `value` (already coerced) is acceptable, else the reason.
std::string check_value(const Operation& op, const ParamDecl& p, const ArgValue& value) {
  if (p.type == ParamType::kEnum) {
    const auto& s = std::get<std::string>(value);
    const bool index = takes_index(p) && is_index_text(s);
    if (!index && (s == kIndexChoice ||
                   std::find(p.choices.begin(), p.choices.end(), s) == p.choices.end())) {
      return concat({op.name, ": parameter '", p.name, "' must be one of ", join(p.choices, ", "),
                     "; got '", s, "'"});
    }
  }
  for (double v : checked_numbers(value)) {
    if (!std::isfinite(v)) {
      return concat({op.name, ": parameter '", p.name, "' must be finite; got ", number_text(v)});
    }
    if (p.min && v < *p.min) {
      return concat({op.name, ": parameter '", p.name, "' must be >= ", number_text(*p.min),
                     "; got ", number_text(v)});
    }
    if (p.max && v > *p.max) {
      return concat({op.name, ": parameter '", p.name, "' must be <= ", number_text(*p.max),
                     "; got ", number_text(v)});
    }
  }
  return {};
}

}  // namespace

std::optional<SizeSpec> parse_size(std::string_view text) {
  SizeSpec size;
  if (!text.empty() && (text.front() == '\'' || text.front() == '~')) {
    size.mode = text.front() == '\'' ? SizeMode::kRelative : SizeMode::kFloating;
    text.remove_prefix(1);
  }
  if (text.empty()) return std::nullopt;
  const std::string copy(text);
  char* end = nullptr;
  size.value = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size() || !std::isfinite(size.value)) return std::nullopt;
  return size;
}

std::string to_string(const SizeSpec& size) {
  switch (size.mode) {
    case SizeMode::kAbsolute:
      return number_text(size.value);
    case SizeMode::kRelative:
      return concat({"'", number_text(size.value)});
    case SizeMode::kFloating:
      return concat({"~", number_text(size.value)});
  }
  return {};
}

std::string_view param_type_name(ParamType type) {
  switch (type) {
    case ParamType::kNumber:
      return "number";
    case ParamType::kInteger:
      return "integer";
    case ParamType::kString:
      return "string";
    case ParamType::kBool:
      return "bool";
    case ParamType::kEnum:
      return "enum";
    case ParamType::kSize:
      return "size";
    case ParamType::kSizeList:
      return "size list";
  }
  return {};
}

std::string to_string(const ArgValue& value) {
  if (const auto* d = std::get_if<double>(&value)) return number_text(*d);
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* z = std::get_if<SizeSpec>(&value)) return to_string(*z);
  std::vector<std::string> parts;
  for (const SizeSpec& s : std::get<std::vector<SizeSpec>>(value)) parts.push_back(to_string(s));
  return concat({"[", join(parts, ", "), "]"});
}

const ArgValue* Arguments::get(std::string_view name) const {
  auto it = values_.find(name);
  return it == values_.end() ? nullptr : &it->second;
}

namespace {
template <typename T>
const T* typed(const Arguments& args, std::string_view name) {
  const ArgValue* v = args.get(name);
  return v == nullptr ? nullptr : std::get_if<T>(v);
}
}  // namespace

double Arguments::number(std::string_view name) const {
  const auto* v = typed<double>(*this, name);
  return v != nullptr ? *v : 0.0;
}

std::int64_t Arguments::integer(std::string_view name) const {
  const auto* v = typed<std::int64_t>(*this, name);
  return v != nullptr ? *v : 0;
}

const std::string& Arguments::string(std::string_view name) const {
  static const std::string kEmpty;
  const auto* v = typed<std::string>(*this, name);
  return v != nullptr ? *v : kEmpty;
}

bool Arguments::boolean(std::string_view name) const {
  const auto* v = typed<bool>(*this, name);
  return v != nullptr && *v;
}

SizeSpec Arguments::size(std::string_view name) const {
  const auto* v = typed<SizeSpec>(*this, name);
  return v != nullptr ? *v : SizeSpec{};
}

const std::vector<SizeSpec>& Arguments::sizes(std::string_view name) const {
  static const std::vector<SizeSpec> kEmpty;
  const auto* v = typed<std::vector<SizeSpec>>(*this, name);
  return v != nullptr ? *v : kEmpty;
}

const ParamDecl* Operation::param(std::string_view param_name) const {
  for (const ParamDecl& p : params) {
    if (p.name == param_name) return &p;
  }
  return nullptr;
}

Registry::Registry(std::vector<Operation> operations) : operations_(std::move(operations)) {
  std::sort(operations_.begin(), operations_.end(),
            [](const Operation& a, const Operation& b) { return a.name < b.name; });
}

const Operation* Registry::find(std::string_view name) const {
  auto it = std::lower_bound(operations_.begin(), operations_.end(), name,
                             [](const Operation& op, std::string_view n) { return op.name < n; });
  return it != operations_.end() && it->name == name ? &*it : nullptr;
}

BindResult Registry::bind(const Operation& op, const std::vector<ArgInput>& inputs) {
  BindResult result;
  std::size_t position = 0;
  for (const ArgInput& input : inputs) {
    const ParamDecl* p = nullptr;
    if (input.name.empty()) {
      if (position >= op.params.size()) {
        result.error = concat({op.name, ": too many arguments (expects at most ",
                               std::to_string(op.params.size()), ")"});
        return result;
      }
      p = &op.params[position++];
    } else if (p = op.param(input.name); p == nullptr) {
      result.error = concat({op.name, ": unknown parameter '", input.name, "'"});
      return result;
    }
    if (result.arguments.has(p->name)) {
      result.error = concat({op.name, ": parameter '", p->name, "' given twice"});
      return result;
    }
    ArgValue value;
    if (!coerce(*p, input.value, value)) {
      result.error = concat({op.name, ": parameter '", p->name, "' expects ", expected_kind(*p),
                             "; got ", value_kind(input.value)});
      return result;
    }
    if (result.error = check_value(op, *p, value); !result.ok()) return result;
    result.arguments.set(p->name, std::move(value));
  }
  for (const ParamDecl& p : op.params) {
    if (result.arguments.has(p.name)) continue;
    if (!p.default_value) {
      result.error = concat({op.name, ": missing required parameter '", p.name, "'"});
      return result;
    }
    result.arguments.set(p.name, *p.default_value);
  }
  return result;
}

OpResult Registry::run(ShapeTree& tree, ShapeId shape, std::string_view name,
                       const std::vector<ArgInput>& inputs, const Context& context) const {
  const Operation* op = find(name);
  if (op == nullptr) return OpResult::failure(concat({"unknown operation '", name, "'"}));
  if (!tree.contains(shape)) {
    return OpResult::failure(concat({op->name, ": no shape ", std::to_string(shape)}));
  }
  BindResult bound = bind(*op, inputs);
  if (!bound.ok()) return OpResult::failure(std::move(bound.error));
  const std::size_t before = tree.size();
  OpResult result = op->execute(tree, shape, bound.arguments, context);
  if (!result.ok()) {
    tree.truncate(before);  // a failed operation leaves no partial children behind
    result.children.clear();
    result.pieces.clear();
    result.error = concat({op->name, ": ", result.error});
  }
  return result;
}

namespace {

struct Amendments {
  std::vector<std::function<void(std::vector<Operation>&)>> pending;
  bool built = false;
};
Amendments& amendments() {
  static Amendments kAmendments;
  return kAmendments;
}

}  // namespace

bool extend_registry(std::function<void(std::vector<Operation>&)> amend) {
  Amendments& a = amendments();
  if (a.built) return false;
  a.pending.push_back(std::move(amend));
  return true;
}

const Registry& registry() {
  static const Registry kRegistry = [] {
    std::vector<Operation> all;
    for (auto* family :
         {&extrude_operations,   &split_operations,     &comp_operations,
          &transform_operations, &offset_operations,    &roof_operations,
          &insert_operations,    &scope_operations,     &inner_rectangle_operations,
          &cleanup_operations,   &primitive_operations, &convexify_operations,
          &component_operations, &stair_operations,     &frame_operations,
          &slab_operations,      &wall_operations,      &uv_operations,
          &scatter_operations,   &envelope_operations,  &insert_along_uv_operations}) {
      for (Operation& op : (*family)()) all.push_back(std::move(op));
    }
    Amendments& a = amendments();
    for (const auto& amend : a.pending) amend(all);
    a.built = true;
    return Registry(std::move(all));
  }();
  return kRegistry;
}

namespace {

std::string param_row(const ParamDecl& p) {
  std::string type(param_type_name(p.type));
  if (p.type == ParamType::kEnum) type = join(p.choices, " \\| ");
  if (p.min && p.max) {
    type.append(concat({" in [", number_text(*p.min), ", ", number_text(*p.max), "]"}));
  } else if (p.min) {
    type.append(concat({" >= ", number_text(*p.min)}));
  } else if (p.max) {
    type.append(concat({" <= ", number_text(*p.max)}));
  }
  const std::string value =
      p.default_value ? concat({"`", to_string(*p.default_value), "`"}) : "required";
  return concat({"| `", p.name, "` | ", type, " | ", value, " | ", p.doc, " |\n"});
}

// A table cell: the spellings one per line, `|` escaped.
std::string spelling_cell(const std::vector<std::string>& spellings) {
  std::string out;
  for (const std::string& s : spellings) {
    if (!out.empty()) out.append("<br>");
    out.append("`");
    for (char c : s) {
      if (c == '|') out.push_back('\\');
      out.push_back(c);
    }
    out.append("`");
  }
  return out.empty() ? "-" : out;
}

std::string spelling_table(std::span<const FrontEndSpellings> front_ends) {
  std::string out = "\n## Spellings by front-end\n\n| operation |";
  std::string rule = "|---|";
  for (const FrontEndSpellings& f : front_ends) {
    out.append(concat({" ", f.name, " |"}));
    rule.append("---|");
  }
  out.append(concat({"\n", rule, "\n"}));
  for (const Operation& op : registry().operations()) {
    out.append(concat({"| `", op.name, "` |"}));
    for (const FrontEndSpellings& f : front_ends) {
      out.append(
          concat({" ", spelling_cell(f.spell ? f.spell(op) : std::vector<std::string>{}), " |"}));
    }
    out.append("\n");
  }
  return out;
}

}  // namespace

std::string operations_reference_markdown() {
  return operations_reference_markdown({});
}

std::string operations_reference_markdown(std::span<const FrontEndSpellings> front_ends) {
  std::string out =
      "# Shape operations\n\n"
      "Generated from the operation registry (`src/shape/ops_*.cc`) and the front-ends' "
      "spellings by\n"
      "`insula::shape::operations_reference_markdown()`; "
      "`tests/lang/frontends/operations_doc_test.cc`\n"
      "fails when this file differs. Regenerate with `INSULA_REGENERATE=1 "
      "build/tests/lang/test_lang_frontends_operations_doc_test`.\n\n"
      "Every front-end (CGA, Lua, graphs, the building grammar, PLaSM) calls these through\n"
      "`registry().run(tree, shape, name, arguments)`. Arguments are positional (declaration "
      "order)\n"
      "or named. Sizes are written `2` (meters), `'0.5` (relative: a fraction of the scope size) "
      "or\n"
      "`~1` (floating: a weight sharing what is left). Argument errors read:\n\n"
      "- `unknown operation 'NAME'`\n"
      "- `OP: unknown parameter 'NAME'`\n"
      "- `OP: too many arguments (expects at most N)`\n"
      "- `OP: parameter 'NAME' given twice`\n"
      "- `OP: parameter 'NAME' expects a number; got a string` (or an integer, a bool, a size, a\n"
      "  size list, one of a, b, c)\n"
      "- `OP: parameter 'NAME' must be one of a, b, c; got 'VALUE'`\n"
      "- `OP: parameter 'NAME' must be >= MIN; got VALUE` (and `<= MAX`, `must be finite`)\n"
      "- `OP: missing required parameter 'NAME'`\n\n"
      "An operation creates children of the shape it runs on and marks that shape inactive; a\n"
      "failed operation leaves the tree as it was.\n";
  if (!front_ends.empty()) out.append(spelling_table(front_ends));
  for (const Operation& op : registry().operations()) {
    out.append(concat({"\n## ", op.name, "\n\n", op.doc, "\n"}));
    if (op.params.empty()) continue;
    out.append("\n| parameter | type | default | description |\n|---|---|---|---|\n");
    for (const ParamDecl& p : op.params) out.append(param_row(p));
  }
  return out;
}

}  // namespace insula::shape
