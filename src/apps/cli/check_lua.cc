// `insula check FILE.lua`: compiles the program without running it (a program is code: what it
// builds is only known by running it, which `insula build` does in the sandbox). Syntax errors are
// reported as file:line:col with code LUA001.
#include <optional>
#include <string>

#include "apps/cli/front_ends.h"
#include "lang/lua/runtime.h"

namespace insula::cli {

std::optional<std::string> check_lua(const base::Source& source, bool quiet) {
  const std::vector<base::Diagnostic> diagnostics = lua::Runtime::check(source);
  print_diagnostics(diagnostics, source, quiet);
  if (base::has_errors(diagnostics)) return std::nullopt;
  std::size_t lines = 0;
  for (char c : source.text()) lines += c == '\n' ? 1 : 0;
  return "Lua program compiles (" + std::to_string(lines) + " lines)";
}

}  // namespace insula::cli
