#include "lang/lua/operations.h"

#include <algorithm>

namespace insula::lua {

namespace {

bool is_lua_keyword(std::string_view name) {
  static constexpr std::string_view kKeywords[] = {
      "and",      "break",  "do",   "else", "elseif", "end",  "false", "for",
      "function", "goto",   "if",   "in",   "local",  "nil",  "not",   "or",
      "repeat",   "return", "then", "true", "until",  "while"};
  return std::find(std::begin(kKeywords), std::end(kKeywords), name) != std::end(kKeywords);
}

}  // namespace

std::string global_name(std::string_view name) {
  std::string out(name);
  if (is_lua_keyword(name)) out += "Split";
  return out;
}

std::vector<std::string> lua_spellings(const shape::Operation& op) {
  // split keeps seed 001's labelled pieces (bind_ops.cc lua_split).
  if (op.name == "split") return {"split(c, axis, piece, ...)"};
  std::string text = global_name(op.name) + "(c";
  for (const shape::ParamDecl& p : op.params) text += ", " + p.name;
  text += ", {name=value, ...})";
  return {text};
}

}  // namespace insula::lua
