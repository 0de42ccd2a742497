// Expressions of parameter values (graph-format.md §5): a parser with positions and a type
// checker. An expression is the text after the `=` of a string value; positions are byte
// indices into that text (string_byte_offset turns them into file offsets).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lang/graph/types.h"

namespace insula::lang::graph {

struct Expr {
  enum class Kind : std::uint8_t {
    kNumber,
    kInteger,
    kString,
    kBool,
    kList,
    kAttribute,      // @name
    kPortAttribute,  // port@name (`port` in `scope`)
    kParameter,      // name
    kCall,           // name(args)
    kUnary,          // op: "-" or "not"
    kBinary,         // op: or and == != < <= > >= + - * / %
    kMember,         // args[0].x (name "x", "y" or "z")
    kIndex,          // args[0][args[1]]
  };
  Kind kind = Kind::kNumber;
  std::size_t begin = 0;  // first byte of the expression's text
  std::size_t end = 0;    // one past its last byte
  std::size_t at = 0;     // the byte a diagnostic about it points at (an operator, a name)
  std::string name;       // parameter, attribute, function or operator
  std::string scope;      // kPortAttribute: the port
  double number = 0;
  std::int64_t integer = 0;
  bool boolean = false;
  std::string text;
  std::vector<Expr> args;
};

struct ExprError {
  std::string code;  // G020, G021, G022, G023, G024, G012
  std::string message;
  std::size_t at = 0;
};

// Parses `text` (without the leading `=`); nesting is bounded (G023 past 100 levels).
std::optional<Expr> parse_expression(std::string_view text, ExprError& error);

// What a type check may look up: graph attributes and parameters, the node's input ports, and
// whether `@` may be read (false in a per-round parameter of a collective node: G022).
struct ExprScope {
  std::function<std::optional<ValueType>(const std::string&)> attribute;
  std::function<std::optional<ValueType>(const std::string&)> parameter;
  std::function<bool(const std::string&)> input_port;
  std::vector<std::string> attributes;  // for suggestions
  std::vector<std::string> parameters;
  bool entity_readable = true;
  std::string not_readable_because;  // G022's message up to "cannot read '@x'"
};

// The expression's type (kAny when it depends on a list's element), or the first error.
std::optional<ValueType> check_expression(const Expr& expr, std::string_view text,
                                          const ExprScope& scope, ExprError& error);

}  // namespace insula::lang::graph
