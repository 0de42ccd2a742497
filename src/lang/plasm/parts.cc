#include "lang/plasm/parts.h"

#include "lang/plasm/checker.h"
#include "lang/plasm/output.h"
#include "lang/plasm/parser.h"

namespace insula::lang::plasm {

std::pair<std::string, std::string> split_part_name(std::string_view name) {
  const std::size_t hash = name.find('#');
  if (hash == std::string_view::npos) return {std::string(name), {}};
  return {std::string(name.substr(0, hash)), std::string(name.substr(hash + 1))};
}

namespace {

std::string first_error(const std::vector<base::Diagnostic>& diagnostics) {
  for (const base::Diagnostic& d : diagnostics)
    if (d.severity == base::Severity::kError) return base::render(d);
  return "failed";
}

}  // namespace

std::shared_ptr<const kernel::Mesh> part_mesh(const base::Source& file, std::string_view expression,
                                              std::string& error, Budgets budgets) {
  // The expression is parsed as one more statement of the file, so the file's DEFs are in
  // scope and a diagnostic in it points past the file's last line, at the expression.
  std::string text = file.text();
  if (!expression.empty()) {
    text += "\n";
    text += expression;
    text += ";\n";
  }
  const base::Source source(file.name() + (expression.empty() ? "" : "#expression"), text);
  base::Result<Program> program = parse(source);
  if (!program.ok()) {
    error = first_error(program.diagnostics());
    return nullptr;
  }
  const CheckResult checked = check(program.value(), source);
  if (!checked.ok) {
    error = first_error(checked.diagnostics);
    return nullptr;
  }
  std::size_t last = program->statements.size();
  while (last > 0 && program->statements[last - 1].is_def) --last;
  if (last == 0) {
    error = file.name() + ": no expression to insert (name one: FILE.psm#expression)";
    return nullptr;
  }
  Evaluator evaluator(program.value(), source, budgets);
  base::Result<ValuePtr> value = evaluator.statement(last - 1);
  if (!value.ok()) {
    error = first_error(value.diagnostics());
    return nullptr;
  }
  if (!value.value()->is_polyhedron()) {
    error = file.name() + ": the expression gives " + kind_name(value.value()->kind()) +
            ", not a polyhedron";
    return nullptr;
  }
  MeshStats stats;
  const shape::Building building = polyhedron_building(*value.value()->polyhedron(), "part", stats);
  auto mesh = std::make_shared<kernel::Mesh>();
  for (const shape::Part& part : building.parts) mesh->append(part.mesh);
  if (mesh->empty()) {
    error = file.name() + ": the expression gives a polyhedron without area";
    return nullptr;
  }
  for (kernel::Vec3& p : mesh->positions()) p = {p.x, p.z, -p.y};
  return mesh;
}

}  // namespace insula::lang::plasm
