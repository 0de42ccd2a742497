// One .bldg grammar through seed 000's pipeline (floor plan §3.2-3.4, 3D model §3.4/§4.1/§4.6) for
// `insula build FILE.bldg`: a single building (build_bldg.cc) or a village of lots
// (bldg_village.h). What a building says is kept as Messages, printed at once by a sequential build
// or carried to the leader of a tile job and printed there in lot order.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/cli/build_command.h"
#include "base/diagnostic.h"
#include "io/footprint_finish.h"
#include "lang/bldg/builder.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/restrictions.h"

namespace insula::cli {

// "insula: error: MESSAGE" on stderr.
void print_error(const std::string& message);

// Errors and warnings in the order they were met.
class Messages {
 public:
  void error(std::string line) { lines_.emplace_back(std::string(), std::move(line)); }
  void warning(std::string code, std::string line) {
    lines_.emplace_back(std::move(code), std::move(line));
  }
  void diagnostics(const std::vector<base::Diagnostic>& diagnostics, const base::Source& source);
  // Errors to stderr; warnings counted and capped (warnings.h), printed unless `quiet`.
  void print(bool quiet) const;
  nlohmann::json json() const;
  static Messages from_json(const nlohmann::json& j);

 private:
  std::vector<std::pair<std::string, std::string>> lines_;  // (warning code, line); "": error
};

struct Parsed {
  std::unique_ptr<base::Source> source;
  lang::bldg::Building building;
};
// The grammar at `path`, or nullopt with the reason printed.
std::optional<Parsed> parse_file(const BuildOptions& options, const std::string& path);

// One grammar through the pipeline: parsed (already), floor plan, 3D model.
struct Built {
  lang::bldg::FloorPlan plan;
  lang::bldg::BuildResult result;
  double plan_seconds = 0;
  double build_seconds = 0;
};

// `lot` names the lot the building stands on in its warnings (empty: an inline outline). With
// `skipped` given (a lot under --keep-going), a lot error is not told but returned there.
// A lot is planned and built at its own origin and the plan and building moved back (lot_origin
// in bldg_pipeline.cc), so the result does not depend on the lot file's origin; an inline outline
// is planned where it is.
std::optional<Built> plan_and_build(const base::Source& source, lang::bldg::Building building,
                                    const lang::bldg::Restrictions& rules, const std::string& lot,
                                    Messages& messages,
                                    std::optional<base::Diagnostic>* skipped = nullptr);

// Names a lot in warnings and in the report: its position in the file and its id.
std::string lot_name(const io::Footprint& lot);

// A building's report: rooms, doors, entrances, windows, stairs, unreachable rooms, counts,
// adaptations, vertices, triangles, warnings.
nlohmann::json plan_report(const lang::bldg::FloorPlan& plan, const lang::bldg::BuildResult& built);
// What the floor plan changed to fit the grammar to the lot, and their sum over buildings.
nlohmann::json adaptations_report(const lang::bldg::PlanAdaptations& adaptations);
void add_adaptations(nlohmann::json& total, const nlohmann::json& one);
// The stages' seconds of one building, and their sum into report["seconds"].
nlohmann::json stage_seconds(const Built& built);
void add_seconds(nlohmann::json& report, const nlohmann::json& seconds);

}  // namespace insula::cli
