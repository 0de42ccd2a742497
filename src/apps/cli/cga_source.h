// A CGA rule file as users have it (issue 20, item 5): any encoding CityEngine writes (UTF-8,
// a byte order mark, Windows-1252), any line ending, and its imports read from disk as
// CityEngine finds them (docs/cityengine-dialect.md, "Files").
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::cli {

struct CgaSource {
  // Every file of the grammar (the rule file, then each imported one): the grammar's ranges
  // refer to it.
  std::unique_ptr<base::Source> source;
  base::Result<lang::cga::Grammar> grammar;
};

// Parses `bytes` read from `path` and merges its imports. Diagnostics (errors make the result a
// failure) include a warning when the file was not UTF-8.
CgaSource load_cga(const std::string& path, const std::string& bytes);

// Where `import alias : "name"` finds `name` from rule file `from`: relative to `from`'s folder,
// then to the project's `rules/` folder (the nearest folder above `from` holding `rules/` or
// `assets/`); a name starting with `/` (a workspace path, `/ESRI.lib/rules/x.cga`) is looked up
// under each folder above `from`. Returns the candidates in that order.
std::vector<std::string> import_candidates(const std::string& name, const std::string& from);

}  // namespace insula::cli
