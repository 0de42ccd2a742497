// List operations (graph-format.md §11 "List operations"): collective nodes that decide by
// looking at the whole list; order is kept wherever the format does not say otherwise.
#include <algorithm>
#include <limits>
#include <numeric>

#include "lang/graph/nodes.h"

namespace insula::lang::graph {
namespace {

std::span<const EntityId> all(NodeContext& c) {
  return c.input(0, c.input_port("in"));
}

void count(NodeContext& c) {
  const std::span<const EntityId> in = all(c);
  const auto n = static_cast<std::int64_t>(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    c.write(in[i], "index", Value(static_cast<std::int64_t>(i)));
    c.write(in[i], "count", Value(n));
    c.emit(c.output_port("out"), in[i]);
  }
}

// The `by` key of each entity: a list value per entity ([] when not given: one group).
std::vector<Value> keys(NodeContext& c, std::string_view param, std::span<const EntityId> in) {
  std::vector<Value> out;
  out.reserve(in.size());
  for (EntityId e : in) out.push_back(c.param_on(0, param, e));
  return out;
}

// Groups by equal keys in order of first appearance: group index per entity.
std::vector<std::size_t> group_of(const std::vector<Value>& keys, std::size_t& groups) {
  std::vector<std::size_t> index(keys.size());
  std::vector<const Value*> seen;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    std::size_t g = 0;
    while (g < seen.size() && !(*seen[g] == keys[i])) ++g;
    if (g == seen.size()) seen.push_back(&keys[i]);
    index[i] = g;
  }
  groups = seen.size();
  return index;
}

void amount_filter(NodeContext& c) {
  const std::span<const EntityId> in = all(c);
  const std::int64_t start = c.param(0, "start").integer();
  const std::int64_t amount = c.param(0, "amount").integer();
  std::size_t groups = 0;
  const std::vector<std::size_t> group = group_of(keys(c, "by", in), groups);
  std::vector<std::int64_t> seen(groups, 0);
  for (std::size_t i = 0; i < in.size(); ++i) {
    const std::int64_t k = seen[group[i]]++;
    const bool taken = k >= start && k < start + amount;
    c.emit(c.output_port(taken ? "taken" : "rest"), in[i]);
  }
}

// Numbers compare numerically, strings by bytes, bools false < true; mixed types by type.
bool less(const Value& a, const Value& b) {
  if (a.is_number() && b.is_number()) return a.number() < b.number();
  if (a.type() != b.type()) return a.type() < b.type();
  switch (a.type()) {
    case ValueType::kString:
      return a.text() < b.text();
    case ValueType::kBool:
      return !a.boolean() && b.boolean();
    default:
      return false;
  }
}

void order_by(NodeContext& c) {
  const std::span<const EntityId> in = all(c);
  const std::size_t criteria = c.augment_count();
  std::vector<std::vector<Value>> values(criteria);
  std::vector<bool> descending(criteria);
  for (std::size_t k = 0; k < criteria; ++k) {
    for (EntityId e : in) values[k].push_back(c.field(0, k, "value", e));
    descending[k] = c.field(0, k, "descending", kNoEntity).boolean();
  }
  std::vector<std::size_t> order(in.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    for (std::size_t k = 0; k < criteria; ++k) {
      const Value& x = values[k][a];
      const Value& y = values[k][b];
      if (less(x, y)) return !descending[k];
      if (less(y, x)) return static_cast<bool>(descending[k]);
    }
    return false;
  });
  for (std::size_t i : order) c.emit(c.output_port("out"), in[i]);
}

void reverse(NodeContext& c) {
  const std::span<const EntityId> in = all(c);
  for (std::size_t i = in.size(); i-- > 0;) c.emit(c.output_port("out"), in[i]);
}

// Fisher-Yates over a stream seeded by (graph seed, node id, `seed`).
void shuffle(NodeContext& c) {
  const std::span<const EntityId> in = all(c);
  std::vector<EntityId> list(in.begin(), in.end());
  shape::Rng rng = c.rng(kNoEntity, "shuffle:" + std::to_string(c.param(0, "seed").integer()));
  for (std::size_t i = list.size(); i > 1; --i) {
    const auto j = static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(i) - 1));
    std::swap(list[i - 1], list[j]);
  }
  for (EntityId e : list) c.emit(c.output_port("out"), e);
}

// "Aggregator" (§4.2): per group, the result written on every member.
void aggregate(NodeContext& c) {
  const std::span<const EntityId> in = all(c);
  const std::string op = c.param(0, "op").text();
  std::size_t groups = 0;
  const std::vector<std::size_t> group = group_of(keys(c, "by", in), groups);
  std::vector<Value> values;
  for (EntityId e : in) values.push_back(c.param_on(0, "value", e));
  for (std::size_t g = 0; g < groups; ++g) {
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < in.size(); ++i) {
      if (group[i] == g) members.push_back(i);
    }
    Value result;
    if (op == "count") {
      result = Value(static_cast<std::int64_t>(members.size()));
    } else if (values[members.front()].type() == ValueType::kVec3) {
      kernel::Vec3 sum;
      for (std::size_t i : members) {
        if (values[i].type() != ValueType::kVec3) c.error("'value' mixes vec3 and other types");
        sum = sum + values[i].vec();
      }
      if (op != "sum" && op != "average") c.error("min and max need numbers, not vec3");
      result = Value(op == "sum" ? sum : sum / static_cast<double>(members.size()));
    } else {
      double acc = op == "min" ? 1e308 : op == "max" ? -1e308 : 0;
      // Integers are summed and compared exactly (a double loses them past 2^53).
      bool integers = true;
      bool overflow = false;
      std::int64_t sum = 0;
      std::int64_t lo = std::numeric_limits<std::int64_t>::max();
      std::int64_t hi = std::numeric_limits<std::int64_t>::min();
      for (std::size_t i : members) {
        if (!values[i].is_number())
          c.error("'value' must be a number; got " + to_string(values[i]));
        integers = integers && values[i].type() == ValueType::kInteger;
        if (integers) {
          const std::int64_t n = values[i].integer();
          overflow = overflow || __builtin_add_overflow(sum, n, &sum);
          lo = std::min(lo, n);
          hi = std::max(hi, n);
        }
        const double x = values[i].number();
        acc = op == "min" ? std::min(acc, x) : op == "max" ? std::max(acc, x) : acc + x;
      }
      if (op == "average" || !integers) {
        result = Value(op == "average" ? acc / static_cast<double>(members.size()) : acc);
      } else if (op == "sum") {
        if (overflow) c.error("integer overflow in the sum of 'value'");
        result = Value(sum);
      } else {
        result = Value(op == "min" ? lo : hi);
      }
    }
    for (std::size_t i : members) c.write(in[i], "result", result);
  }
  for (EntityId e : in) c.emit(c.output_port("out"), e);
}

// "Group": one group entity per key, members in order; it carries the attribute values all
// its members share.
void group(NodeContext& c) {
  const std::span<const EntityId> in = all(c);
  std::size_t groups = 0;
  const std::vector<std::size_t> index = group_of(keys(c, "by", in), groups);
  for (std::size_t g = 0; g < groups; ++g) {
    const EntityId out = c.create(0, EntityType::kGroup, static_cast<std::uint32_t>(g));
    std::vector<EntityId> members;
    for (std::size_t i = 0; i < in.size(); ++i) {
      if (index[i] == g) members.push_back(in[i]);
    }
    for (const auto& [key, value] : c.entities().attributes(members.front())) {
      bool common = true;
      for (EntityId m : members) {
        const Value* v = c.entities().attribute(m, key);
        common = common && v != nullptr && *v == *value;
      }
      if (common) c.entities().set_attribute(out, key, *value);
    }
    c.entities()[out].members = members;
    c.write(out, "size", Value(static_cast<std::int64_t>(members.size())));
    c.emit(c.output_port("out"), out);
  }
}

// Members in order; they take the group's attributes they lack.
void ungroup(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId g = c.current(r);
    const std::vector<EntityId> members = c.entities()[g].members;
    const auto group_values = c.entities().attributes(g);
    for (EntityId m : members) {
      for (const auto& [key, value] : group_values) {
        if (c.entities().attribute(m, key) == nullptr) c.entities().set_attribute(m, key, *value);
      }
      c.emit(c.output_port("out"), m);
    }
  }
}

constexpr NodeImpl kNodes[] = {
    {"list.count", count},       {"list.amount_filter", amount_filter},
    {"list.order_by", order_by}, {"list.reverse", reverse},
    {"list.shuffle", shuffle},   {"list.aggregate", aggregate},
    {"list.group", group},       {"list.ungroup", ungroup},
};

}  // namespace

std::span<const NodeImpl> list_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
