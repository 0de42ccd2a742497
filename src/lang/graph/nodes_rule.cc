// Rule nodes (an extension of the format, docs/graph-executor.md "Rule nodes"): a CGA rule file,
// a .bldg grammar or a Lua program run on each shape's footprint through the app's RuleRunner
// (one front-end never includes another), and a PLaSM expression inserted into the scope. The
// programs run in parallel; their models are attached in round order, so the output does not
// depend on --threads.
#include <tbb/parallel_for.h>

#include <cmath>

#include "lang/graph/executor.h"
#include "lang/graph/nodes.h"
#include "lang/graph/shape_entities.h"

namespace insula::lang::graph {
namespace {

// The outline's edge along the scope's x axis at y = 0 (a lot's first edge, a facade's bottom),
// so the program's scope x follows the graph's.
std::optional<std::array<kernel::Vec2, 2>> scope_x_edge(const kernel::Polygon& outline) {
  const kernel::Ring& ring = outline.outer;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const kernel::Vec2 a = ring[i];
    const kernel::Vec2 b = ring[(i + 1) % ring.size()];
    if (std::abs(a.y) < 1e-6 && std::abs(b.y) < 1e-6 && b.x > a.x) {
      return std::array<kernel::Vec2, 2>{a, b};
    }
  }
  return std::nullopt;
}

template <const char* kLanguage>
void rule(NodeContext& c) {
  if (c.options().rules == nullptr) c.error("no front-ends are plugged in to run rule files");
  const std::size_t n = c.rounds();
  std::vector<RuleRequest> requests(n);
  std::vector<bool> usable(n, false);
  for (std::size_t r = 0; r < n; ++r) {
    const EntityId in = c.current(r);
    RuleRequest& q = requests[r];
    q.language = kLanguage;
    q.file = c.param(r, "file").text();
    if (c.checked().type->param("start") != nullptr) q.start = c.param(r, "start").text();
    const shape::Shape& s = c.tree()[c.entities()[in].shape];
    if (s.outline == nullptr) {
      c.fail(in, q.language + " rules need a flat shape (a lot, a facade)");
      continue;
    }
    q.outline = *s.outline;
    q.scope = s.scope;
    q.first_edge = scope_x_edge(*s.outline);
    for (const auto& [name, value] : c.stored_attributes(in)) {
      switch (value.type()) {
        case ValueType::kBool:
          q.attributes[name] = value.boolean();
          break;
        case ValueType::kString:
          q.attributes[name] = value.text();
          break;
        case ValueType::kNumber:
        case ValueType::kInteger:
          q.attributes[name] = value.number();
          break;
        default:
          break;
      }
    }
    q.seed = c.entities()[in].seed;
    std::string problem;
    if (!c.options().rules->prepare(q, problem)) c.error(problem);
    usable[r] = true;
  }
  std::vector<std::shared_ptr<const Model>> models(n);
  std::vector<std::string> errors(n);
  const RuleRunner& runner = *c.options().rules;
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t r) {
    if (usable[r]) models[r] = runner.run(requests[r], errors[r]);
  });
  for (std::size_t r = 0; r < n; ++r) {
    if (!usable[r]) continue;
    const EntityId in = c.current(r);
    if (models[r] == nullptr) {
      c.fail(in, errors[r]);
      continue;
    }
    const EntityId out = c.entities().derive(in, EntityType::kShape);
    c.entities()[out].shape = c.entities()[in].shape;
    c.entities()[out].model = models[r];
    c.emit(c.output_port("out"), out);
  }
}
constexpr char kCga[] = "cga";
constexpr char kBldg[] = "bldg";
constexpr char kLua[] = "lua";

// PLaSM parts come through the asset provider (FILE.psm#EXPRESSION), as CGA's i() gets them.
void plasm(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    std::vector<EntityId> children;
    const std::string file = c.param(r, "file").text();
    if (!run_operation(c, c.current(r), "insert", {{"asset", file}}, children)) continue;
    for (EntityId e : children) c.emit(c.output_port("out"), e);
  }
}

constexpr NodeImpl kNodes[] = {
    {"rule.cga", rule<kCga>},
    {"rule.bldg", rule<kBldg>},
    {"rule.lua", rule<kLua>},
    {"rule.plasm", plasm},
};

}  // namespace

std::span<const NodeImpl> rule_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
