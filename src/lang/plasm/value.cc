#include "lang/plasm/value.h"

#include <algorithm>

#include "base/format.h"
#include "lang/plasm/polyhedron.h"

namespace insula::lang::plasm {
namespace {

constexpr std::size_t kShownElements = 16;
constexpr int kShownDepth = 8;

int depth_of(const Sequence& elements) {
  int depth = 0;
  for (const ValuePtr& e : elements) depth = std::max(depth, e->depth + 1);
  return depth;
}

std::string number_text(double value) {
  return base::shortest_number(value == 0.0 ? 0.0 : value);
}

void append_summary(std::string& out, const Value& value, int level) {
  switch (value.kind()) {
    case Kind::kNumber:
      out += number_text(value.number());
      return;
    case Kind::kBool:
      out += value.boolean() ? "TRUE" : "FALSE";
      return;
    case Kind::kString:
      out += base::quoted_string(value.string());
      return;
    case Kind::kSequence: {
      const Sequence& elements = value.sequence();
      if (level >= kShownDepth && !elements.empty()) {
        out += "<...>";
        return;
      }
      out += '<';
      for (std::size_t i = 0; i < elements.size() && i < kShownElements; ++i) {
        if (i > 0) out += ", ";
        append_summary(out, *elements[i], level + 1);
      }
      if (elements.size() > kShownElements)
        out += ", ... (" + std::to_string(elements.size()) + " elements)";
      out += '>';
      return;
    }
    case Kind::kFunction: {
      const Function& f = value.function();
      out += "<function " + f.label;
      if (f.bound.size() > f.captured) {
        out += ", ";
        out += std::to_string(f.bound.size() - f.captured);
        out += " of ";
        out += std::to_string(f.arity - f.captured);
        out += " arguments";
      }
      out += '>';
      return;
    }
    case Kind::kPolyhedron:
      out += "<polyhedron " + std::to_string(value.polyhedron()->dim) + "D, " +
             std::to_string(cell_count(*value.polyhedron())) + " cells>";
      return;
  }
}

}  // namespace

ValuePtr make_number(double value) {
  return std::make_shared<const Value>(Value{value, 0});
}

ValuePtr make_bool(bool value) {
  return std::make_shared<const Value>(Value{value, 0});
}

ValuePtr make_string(std::string value) {
  return std::make_shared<const Value>(Value{std::move(value), 0});
}

ValuePtr make_sequence(Sequence elements) {
  const int depth = depth_of(elements);
  return std::make_shared<const Value>(Value{std::move(elements), depth});
}

ValuePtr make_function(Function function) {
  const int depth = depth_of(function.bound);
  return std::make_shared<const Value>(Value{std::move(function), depth});
}

ValuePtr make_polyhedron(std::shared_ptr<const Polyhedron> polyhedron) {
  return std::make_shared<const Value>(Value{std::move(polyhedron), 0});
}

std::string kind_name(Kind kind) {
  switch (kind) {
    case Kind::kNumber:
      return "a number";
    case Kind::kBool:
      return "a truth value";
    case Kind::kString:
      return "a string";
    case Kind::kSequence:
      return "a sequence";
    case Kind::kFunction:
      return "a function";
    case Kind::kPolyhedron:
      return "a polyhedron";
  }
  return "a value";
}

std::string summary(const Value& value) {
  std::string out;
  append_summary(out, value, 0);
  return out;
}

bool equal(const ValuePtr& a, const ValuePtr& b) {
  if (a == b) return true;
  if (a->kind() != b->kind()) return false;
  switch (a->kind()) {
    case Kind::kNumber:
      return a->number() == b->number();
    case Kind::kBool:
      return a->boolean() == b->boolean();
    case Kind::kString:
      return a->string() == b->string();
    case Kind::kSequence:
      return std::equal(a->sequence().begin(), a->sequence().end(), b->sequence().begin(),
                        b->sequence().end(),
                        [](const ValuePtr& x, const ValuePtr& y) { return equal(x, y); });
    case Kind::kFunction:
    case Kind::kPolyhedron:
      return false;
  }
  return false;
}

}  // namespace insula::lang::plasm
