#include "apps/cli/cga_source.h"

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "base/text_encoding.h"
#include "io/asset_search.h"
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

}  // namespace

CgaSource load_cga(const std::string& path, const std::string& bytes,
                   const std::string& workspace) {
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
      [&](const std::string& name, const std::string& from,
          std::string& error) -> std::optional<lang::cga::ImportedFile> {
    const io::AssetSearch search(from, workspace);
    if (const std::optional<fs::path> found = search.resolve(name)) {
      if (std::optional<std::string> text = read_bytes(*found)) {
        bool was_converted = false;
        const std::string shown = found->lexically_normal().string();
        lang::cga::ImportedFile file{shown, base::utf8_text(*text, was_converted)};
        if (was_converted) notes.push_back(encoding_note(shown));
        return file;
      }
    }
    error = "no such file (looked for";
    for (const fs::path& candidate : search.candidates(name)) {
      error.append(" ").append(candidate.string());
    }
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
