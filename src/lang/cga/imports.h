// CityEngine's `import alias : "file.cga"` (docs/cityengine-dialect.md §3, "import"): the
// imported file's rules, attributes and functions join the importing grammar under `alias.`
// (`alias.Lot`, `alias.height`), its own imports nested (`a.b.Name`). Attribute propagation: an
// imported attribute takes the value of the importing file's attribute of the same name unless
// the import protects it (`(name)`, or `()` for all); `(name = expr)` overrides it. Positions in
// imported files stay theirs: each file is appended to the one base::Source the grammar's ranges
// refer to. The front-end reads no files: the caller's loader does.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

struct ImportedFile {
  std::string name;  // as diagnostics should name it (the resolved path)
  std::string text;  // UTF-8
};

// Finds and reads `path` imported by file `from`; nullopt with `error` saying where it looked.
using ImportLoader = std::function<std::optional<ImportedFile>(
    const std::string& path, const std::string& from, std::string& error)>;

// Nested imports deeper than this are an error (CGA342), as is a file importing itself (CGA341).
inline constexpr int kMaxImportDepth = 32;

// Merges every import of `grammar` (parsed from `source`) into it, recursively, appending each
// imported file to `source`. Returns the errors (CGA340 file not found, CGA341 import cycle,
// CGA342 too deep, and the imported files' own syntax errors); warnings too.
std::vector<base::Diagnostic> resolve_imports(Grammar& grammar, base::Source& source,
                                              const ImportLoader& load);

}  // namespace insula::lang::cga
