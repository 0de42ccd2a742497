#include "apps/cli/cga_source.h"

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "base/text_encoding.h"
#include "lang/cga/imports.h"
#include "lang/cga/parser.h"

namespace insula::cli {

namespace fs = std::filesystem;

namespace {

base::Diagnostic encoding_note(const std::string& path) {
  return base::Diagnostic::warning("CGA009", "the file is not UTF-8; it was read as Windows-1252",
                                   base::Span::whole(path));
}

std::optional<std::string> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The nearest folder at or above `dir` that looks like a CityEngine project.
std::optional<fs::path> project_of(fs::path dir) {
  std::error_code ec;
  for (; !dir.empty(); dir = dir.parent_path()) {
    if (fs::is_directory(dir / "rules", ec) || fs::is_directory(dir / "assets", ec)) return dir;
    if (dir == dir.parent_path()) break;
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> import_candidates(const std::string& name, const std::string& from) {
  std::vector<std::string> out;
  const fs::path dir = fs::absolute(fs::path(from)).parent_path();
  if (!name.empty() && name.front() == '/') {
    const fs::path tail = fs::path(name).relative_path();
    for (fs::path up = dir; !up.empty(); up = up.parent_path()) {
      out.push_back((up / tail).lexically_normal().string());
      if (up == up.parent_path()) break;
    }
    return out;
  }
  out.push_back((dir / name).lexically_normal().string());
  if (const std::optional<fs::path> project = project_of(dir)) {
    out.push_back((*project / "rules" / name).lexically_normal().string());
  }
  return out;
}

CgaSource load_cga(const std::string& path, const std::string& bytes) {
  bool converted = false;
  CgaSource out{std::make_unique<base::Source>(path, base::utf8_text(bytes, converted)),
                base::Result<lang::cga::Grammar>::failure({})};
  std::vector<base::Diagnostic> notes;
  if (converted) notes.push_back(encoding_note(path));
  base::Result<lang::cga::Grammar> parsed = lang::cga::parse(*out.source);
  for (const base::Diagnostic& d : parsed.diagnostics()) notes.push_back(d);
  if (!parsed.ok()) {
    out.grammar = base::Result<lang::cga::Grammar>::failure(std::move(notes));
    return out;
  }
  lang::cga::Grammar grammar = std::move(parsed.value());
  const lang::cga::ImportLoader loader =
      [&notes](const std::string& name, const std::string& from,
               std::string& error) -> std::optional<lang::cga::ImportedFile> {
    const std::vector<std::string> candidates = import_candidates(name, from);
    for (const std::string& candidate : candidates) {
      std::error_code ec;
      if (!fs::is_regular_file(candidate, ec)) continue;
      std::optional<std::string> text = read_bytes(candidate);
      if (!text) continue;
      bool was_converted = false;
      lang::cga::ImportedFile file{candidate, base::utf8_text(*text, was_converted)};
      if (was_converted) notes.push_back(encoding_note(candidate));
      return file;
    }
    error = "no such file (looked for";
    for (const std::string& candidate : candidates) error.append(" ").append(candidate);
    error += ")";
    return std::nullopt;
  };
  for (base::Diagnostic& d : lang::cga::resolve_imports(grammar, *out.source, loader)) {
    notes.push_back(std::move(d));
  }
  if (base::has_errors(notes)) {
    out.grammar = base::Result<lang::cga::Grammar>::failure(std::move(notes));
  } else {
    out.grammar = base::Result<lang::cga::Grammar>(std::move(grammar), std::move(notes));
  }
  return out;
}

}  // namespace insula::cli
