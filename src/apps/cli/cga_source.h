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

// Parses `bytes` read from `path` and merges its imports, found as assets are (io::AssetSearch
// from the importing file, '/'-names under `workspace`; docs/assets.md). Diagnostics (errors make
// the result a failure) include a warning for each file that was not UTF-8.
CgaSource load_cga(const std::string& path, const std::string& bytes,
                   const std::string& workspace = {});

}  // namespace insula::cli
