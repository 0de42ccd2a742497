#include "apps/cli/graph_rules.h"
#include "apps/cli/cga_source.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>

#include "apps/cli/asset_folders.h"
#include "apps/cli/input_file.h"
#include "lang/bldg/builder.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/parser.h"
#include "lang/cga/checker.h"
#include "lang/cga/compile.h"
#include "lang/cga/derive.h"
#include "lang/cga/parser.h"
#include "lang/lua/runtime.h"

namespace insula::cli {

namespace cga = lang::cga;

struct FrontEndRules::Program {
  bool lua = false;  // a Lua program: `source` run once per shape
  std::unique_ptr<base::Source> source;
  std::unique_ptr<cga::Grammar> grammar;
  std::shared_ptr<const cga::Program> cga;
  std::unique_ptr<lang::bldg::Building> building;  // a .bldg grammar (its outline replaced)
  std::string error;                               // why it cannot run
};

FrontEndRules::FrontEndRules(std::string folder, std::vector<std::string> attributes,
                             const shape::AssetProvider* assets)
    : folder_(std::move(folder)), attributes_(std::move(attributes)), assets_(assets) {
  std::sort(attributes_.begin(), attributes_.end());
}

FrontEndRules::~FrontEndRules() = default;

namespace {

std::string rendered(const std::vector<base::Diagnostic>& diagnostics, const base::Source& source) {
  std::string text;
  for (const base::Diagnostic& d : diagnostics) {
    if (d.severity != base::Severity::kError) continue;
    if (!text.empty()) text += '\n';
    text += base::render(d, &source);
  }
  return text;
}

// The program's text from the graph's folder (confined like assets), or false with the reason
// in program.error.
bool read_source(const std::string& folder, const lang::graph::RuleRequest& request,
                 FrontEndRules::Program& program) {
  std::string why;
  const std::optional<std::filesystem::path> path =
      find_in_folders({folder}, request.file, request.file, why);
  const std::optional<std::string> text =
      path ? read_input_file(path->string()) : std::optional<std::string>();
  if (!text) {
    program.error = "cannot read rule file '" + request.file + "'";
    if (!why.empty()) program.error += ": " + why;
    return false;
  }
  const std::string shown =
      (std::filesystem::path(folder) / request.file).lexically_normal().string();
  program.source = std::make_unique<base::Source>(shown, *text);
  return true;
}

std::unique_ptr<FrontEndRules::Program> read_cga(const std::string& folder,
                                                 const lang::graph::RuleRequest& request,
                                                 const std::vector<std::string>& attributes) {
  auto program = std::make_unique<FrontEndRules::Program>();
  if (!read_source(folder, request, *program)) return program;
  CgaSource loaded = load_cga(program->source->name(), program->source->text());
  program->source = std::move(loaded.source);
  base::Result<cga::Grammar>& grammar = loaded.grammar;
  if (!grammar.ok()) {
    program->error = rendered(grammar.diagnostics(), *program->source);
    return program;
  }
  program->grammar = std::make_unique<cga::Grammar>(std::move(grammar.value()));
  cga::CheckOptions check;
  check.start = request.start;
  check.known_attributes = attributes;
  const cga::CheckResult checked = cga::check(*program->grammar, *program->source, check);
  if (!checked.ok) {
    program->error = rendered(checked.diagnostics, *program->source);
    return program;
  }
  cga::CompileOptions compile;
  compile.start = checked.start_symbol;
  compile.extra_attributes = attributes;
  auto compiled = cga::compile(*program->grammar, *program->source, compile);
  if (!compiled.ok()) {
    program->error = rendered(compiled.diagnostics(), *program->source);
    return program;
  }
  program->cga = compiled.value();
  return program;
}

std::unique_ptr<FrontEndRules::Program> read_bldg(const std::string& folder,
                                                  const lang::graph::RuleRequest& request) {
  auto program = std::make_unique<FrontEndRules::Program>();
  if (!read_source(folder, request, *program)) return program;
  base::Result<lang::bldg::Building> building = lang::bldg::parse_building(*program->source);
  if (!building.ok()) {
    program->error = rendered(building.diagnostics(), *program->source);
    return program;
  }
  program->building = std::make_unique<lang::bldg::Building>(std::move(building.value()));
  return program;
}

// A .bldg building on the shape's outline (the default restriction rules): its parts in scope
// space, or null with the floor planner's diagnostics.
std::shared_ptr<lang::graph::Model> run_bldg(const FrontEndRules::Program& program,
                                             const lang::graph::RuleRequest& request,
                                             std::string& error) {
  lang::bldg::Building building = *program.building;
  building.outline = request.outline;
  const lang::bldg::Restrictions rules;
  lang::bldg::FloorPlanOptions options;
  options.file = program.source->name();
  options.on_lot = true;  // the shape's outline is a lot the grammar was not written for
  base::Result<lang::bldg::FloorPlan> plan = lang::bldg::make_floor_plan(building, rules, options);
  if (!plan.ok()) {
    error = rendered(plan.diagnostics(), *program.source);
    return nullptr;
  }
  lang::bldg::BuildResult built = lang::bldg::build_building(building, plan.value(), rules);
  auto model = std::make_shared<lang::graph::Model>();
  model->materials = std::move(built.materials);
  model->parts = std::move(built.building.parts);
  return model;
}

// A Lua program with the shape's outline as its global `lot` (scope space), in a fresh sandbox.
std::shared_ptr<lang::graph::Model> run_lua(const FrontEndRules::Program& program,
                                            const lang::graph::RuleRequest& request,
                                            const shape::AssetProvider* assets,
                                            std::string& error) {
  lua::RunOptions options;
  options.seed = request.seed;
  options.assets = assets;
  options.lot = request.outline;
  for (const auto& [name, value] : request.attributes) options.params.emplace_back(name, value);
  lua::Runtime runtime(std::move(options));
  const std::vector<base::Diagnostic> diagnostics = runtime.run(*program.source);
  if (base::has_errors(diagnostics)) {
    error = rendered(diagnostics, *program.source);
    return nullptr;
  }
  shape::Scene scene = lua::collect_program(runtime.program());
  auto model = std::make_shared<lang::graph::Model>();
  model->materials = std::move(scene.materials);
  for (shape::Building& b : scene.buildings) {
    for (shape::Part& p : b.parts) model->parts.push_back(std::move(p));
  }
  return model;
}

// The lot was the shape's outline in scope space: the part goes back to the world.
void place(shape::Part& part, const shape::Scope& scope) {
  for (kernel::Vec3& v : part.mesh.positions()) v = scope.to_world(v);
  if (part.uv) part.uv = part.uv->moved(shape::scope_transform(scope));
  if (part.instance_of != nullptr) {
    part.instance_transform = shape::scope_transform(scope) * part.instance_transform;
  }
}

}  // namespace

const FrontEndRules::Program* FrontEndRules::find(const lang::graph::RuleRequest& request) const {
  const std::string key = request.language + ":" + request.file + "#" + request.start;
  const std::lock_guard<std::mutex> lock(mutex_);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    std::unique_ptr<Program> program;
    if (request.language == "cga") {
      program = read_cga(folder_, request, attributes_);
    } else if (request.language == "bldg") {
      program = read_bldg(folder_, request);
    } else if (request.language == "lua") {
      program = std::make_unique<Program>();
      if (read_source(folder_, request, *program)) {
        program->lua = true;
        program->error = rendered(lua::Runtime::check(*program->source), *program->source);
      }
    } else {
      program = std::make_unique<Program>();
      program->error = "rule.";
      program->error += request.language;
      program->error += " nodes cannot run yet in this version";
    }
    it = programs_.emplace(key, std::move(program)).first;
  }
  return it->second.get();
}

bool FrontEndRules::prepare(const lang::graph::RuleRequest& request, std::string& error) const {
  const Program* program = find(request);
  error = program->error;
  return error.empty();
}

std::shared_ptr<const lang::graph::Model> FrontEndRules::run(
    const lang::graph::RuleRequest& request, std::string& error) const {
  const Program* program = find(request);
  if (!program->error.empty()) {
    error = program->error;
    return nullptr;
  }
  if (program->lua) {
    std::shared_ptr<lang::graph::Model> model = run_lua(*program, request, assets_, error);
    if (model != nullptr) {
      for (shape::Part& p : model->parts) place(p, request.scope);
    }
    return model;
  }
  if (program->building != nullptr) {
    std::shared_ptr<lang::graph::Model> model = run_bldg(*program, request, error);
    if (model != nullptr) {
      for (shape::Part& p : model->parts) place(p, request.scope);
    }
    return model;
  }
  cga::Lot lot;
  lot.polygons.push_back(request.outline);
  if (request.first_edge) lot.first_edges.push_back(*request.first_edge);
  lot.properties = request.attributes;
  cga::DeriveOptions options;
  options.seed = request.seed;
  options.assets = assets_;
  std::vector<cga::LotResult> results;
  results.push_back(cga::derive_lot(*program->cga, lot, 0, options));
  if (!results.front().ok) {
    error = rendered(results.front().diagnostics, *program->source);
    return nullptr;
  }
  const std::vector<cga::Lot> lots{lot};
  // One part per symbol and attribute set: a facade's hundreds of terminals become a dozen
  // meshes, so a city of 10,000 lots keeps its parts countable (docs/graph-executor.md).
  // Parts with texture coordinates join only parts with the same map.
  shape::Scene scene = cga::to_scene(*program->cga, lots, std::move(results), false, true);
  auto model = std::make_shared<lang::graph::Model>();
  model->materials = std::move(scene.materials);
  for (shape::Building& b : scene.buildings) {
    for (shape::Part& p : b.parts) {
      place(p, request.scope);
      model->parts.push_back(std::move(p));
    }
  }
  return model;
}

}  // namespace insula::cli
