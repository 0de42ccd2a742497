// Running a checked graph (graph-format.md §9): the queue by execution index, rounds of single
// and collective nodes, transfers with copies on divergence, blocked and leaf ports, subgraph
// rounds with gates and attribute scoping, limits (G050, G051, G053), run-time errors (G052,
// W010, W030, W040) and the counts of the report's `graph` section (§13).
// docs/graph-executor.md, "Execution".
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/polygon.h"
#include "lang/graph/checker.h"
#include "lang/graph/entity.h"
#include "lang/graph/model.h"
#include "shape/operation.h"
#include "shape/scene.h"
#include "shape/scope.h"
#include "shape/shape_tree.h"

namespace insula::lang::graph {

// A lot of `create.lots`: a footprint (local meters, world XY) and its properties.
struct LotInput {
  kernel::Polygon footprint;
  shape::AttributeMap properties;
  std::string id;
  // Its number in the whole input (the `index` attribute and the position its seed mixes in,
  // §9.9), so a lot run with some of its neighbours only gives what it gives in the whole run;
  // none: its place in the list.
  std::optional<std::uint32_t> number{};
};
// Reads the lots of `file` ("" = the command line's --lot), or fails with a reason.
using LotReader =
    std::function<bool(const std::string& file, std::vector<LotInput>& lots, std::string& error)>;

// Runs another front-end's program on a shape (the nodes `rule.cga`, `rule.bldg`, `rule.lua`,
// `rule.plasm`): the app plugs the front-ends in, since one front-end never includes another.
// Must be callable from several threads at once.
struct RuleRequest {
  std::string language;  // "cga", "bldg", "lua", "plasm"
  std::string file;      // as written in the graph (relative to the graph's folder)
  std::string start;     // start rule / function / expression; "" for the program's own
  // The flat shape's outline in its scope's xy plane: the program's lot, in scope space; the
  // runner places what it makes with `scope` (a facade's program sees the wall as its lot).
  kernel::Polygon outline;
  std::optional<std::array<kernel::Vec2, 2>> first_edge;  // the scope x axis' edge, when any
  shape::Scope scope;
  shape::AttributeMap attributes;  // the entity's graph attributes (lot properties)
  std::uint64_t seed = 0;
};
class RuleRunner {
 public:
  virtual ~RuleRunner() = default;
  // Reads and checks the program `request` names, once per program (called on the executor's
  // thread before any run); false with `error` (the program's own diagnostics) stops the run.
  virtual bool prepare(const RuleRequest& request, std::string& error) const = 0;
  // The model, or null with `error` set.
  virtual std::shared_ptr<const Model> run(const RuleRequest& request,
                                           std::string& error) const = 0;
};

struct RunOptions {
  std::optional<std::uint64_t> seed;  // --seed (overrides the graph's)
  // --set name=value for the top-level graph's parameters, as typed on the command line.
  std::vector<std::pair<std::string, std::string>> sets;
  int threads = 1;
  const shape::AssetProvider* assets = nullptr;
  const RuleRunner* rules = nullptr;
  LotReader lots;
  // Lower bounds than the graph's own limits (fuzzing, previews); none: the graph's.
  std::optional<Limits> limits_cap;
  // Polled between node executions; true stops the run (nothing is written).
  std::function<bool()> interrupted;
  // A node ("walls", "houseA/door" inside a subgraph node) whose output entities replace the
  // results: the editor shows what one node made (issue 16). Empty: the graph's results.
  std::string probe;
};

struct PortCount {
  std::uint64_t count = 0;
  std::map<std::string, std::uint64_t> types;  // entity type name -> count
};
struct NodeRuns {
  std::uint64_t executions = 0;
  std::uint64_t rounds = 0;
  double seconds = 0;  // wall time in the node's executions (its subgraph's included)
};

// A result entity: what left a leaf port (§1), in result order.
struct ResultEntity {
  EntityId entity = kNoEntity;
  std::string port;  // "node.port"
};

struct RunResult {
  bool ok = false;
  std::vector<base::Diagnostic> diagnostics;
  std::uint64_t seed = 0;
  shape::ShapeTree tree;
  EntityStore entities;
  std::vector<shape::Material> materials;                            // index 0 = default
  std::map<std::uint16_t, std::shared_ptr<const Texture>> textures;  // by material
  std::vector<ResultEntity> results;  // with RunOptions::probe, what left the probed node
  // The report's counts (§13), keys in first-use order where the format says so.
  std::vector<std::string> cyclic_edges;
  std::vector<std::pair<std::string, NodeRuns>> node_runs;  // node id ("houseA/door" inside)
  std::vector<std::pair<std::string, PortCount>> leaves;    // in order of first arrival
  std::map<std::string, std::uint64_t> blocked;
  // Entities that left each output port ("node.port", "houseA/door.out" inside), blocked ones
  // too: what an editor shows on its ports.
  std::map<std::string, std::uint64_t> ports;
  std::map<std::string, std::uint64_t> unprocessed;
  std::map<std::string, std::uint64_t> failed;
  // The top-level graph's attribute names by key (for reports and the export).
  std::map<AttributeKey, std::string> attribute_names;
  // The entity create.lots made for each lot, and the lot's id ("lot_<number>" when it has none):
  // the export names the buildings of a lot after it.
  std::map<EntityId, std::string> lots;
};

// Runs `document`'s top-level graph (checked by check()). Never throws.
RunResult run_graph(const Document& document, const CheckResult& checked,
                    const RunOptions& options);

}  // namespace insula::lang::graph
