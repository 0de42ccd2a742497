#include "io/obj_reader.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <system_error>

namespace insula::io {
namespace {

using base::Diagnostic;
using base::Span;

constexpr std::size_t kMaxErrors = 50;

struct Token {
  std::string_view text;
  std::uint32_t column = 0;  // 1-based
};

// Splits a line (comment removed) at blanks, keeping 1-based byte columns.
std::vector<Token> tokenize(std::string_view line) {
  if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start)
      tokens.push_back({line.substr(start, i - start), static_cast<std::uint32_t>(start + 1)});
  }
  return tokens;
}

// A number; infinity for one too large for a double (reported as not finite), 0 for one too
// small; none when `text` is not a number.
std::optional<double> parse_double(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || end != text.data() + text.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) {
    const std::size_t e = text.find_first_of("eE");
    const bool tiny = e != std::string_view::npos && e + 1 < text.size() && text[e + 1] == '-';
    return tiny ? 0.0 : std::numeric_limits<double>::infinity();
  }
  if (error != std::errc()) return std::nullopt;
  return value;
}

enum class IntStatus { kOk, kNotANumber, kOutOfRange };

IntStatus parse_int(std::string_view text, long long& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range) return IntStatus::kOutOfRange;
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    return IntStatus::kNotANumber;
  }
  return IntStatus::kOk;
}

// A class name, or the class named by the last '.'-separated component ("b1.main.RoofSurface").
kernel::SemanticClass semantic_of(std::string_view name) {
  if (auto semantic = kernel::semantic_from_name(name)) return *semantic;
  if (const auto dot = name.rfind('.'); dot != std::string_view::npos) {
    if (auto semantic = kernel::semantic_from_name(name.substr(dot + 1))) return *semantic;
  }
  return kernel::SemanticClass::kNone;
}

// Built with append: GCC 12 reports a false -Wrestrict on `"'" + std::string(...)`.
std::string quoted(std::string_view text) {
  constexpr std::size_t kShown = 40;
  std::string out(1, '\'');
  out.append(text.substr(0, kShown));
  if (text.size() > kShown) out.append("...");
  out.push_back('\'');
  return out;
}

class Parser {
 public:
  explicit Parser(std::string source) : source_(std::move(source)) {}
  base::Result<ObjModel> run(std::string_view text);

 private:
  void statement(const std::vector<Token>& tokens);
  void vertex(const std::vector<Token>& tokens);
  void face(const std::vector<Token>& tokens);
  std::optional<std::uint32_t> vertex_reference(const Token& token);
  void use_material(const std::vector<Token>& tokens);
  void error(std::string code, std::string message, const Token& token) {
    diagnostics_.push_back(Diagnostic::error(std::move(code), std::move(message), span(token)));
    ++errors_;
  }
  void warning(std::string code, std::string message, const Token& token) {
    diagnostics_.push_back(Diagnostic::warning(std::move(code), std::move(message), span(token)));
  }
  Span span(const Token& token) const {
    return Span::at(source_, line_, token.column, static_cast<std::uint32_t>(token.text.size()));
  }

  std::string source_;
  std::uint32_t line_ = 0;
  ObjModel model_;
  std::vector<Diagnostic> diagnostics_;
  std::size_t errors_ = 0;
  kernel::SemanticClass group_semantic_ = kernel::SemanticClass::kNone;
  kernel::SemanticClass material_semantic_ = kernel::SemanticClass::kNone;
  kernel::MaterialId material_ = 0;
  std::uint32_t faces_ = 0;
};

base::Result<ObjModel> Parser::run(std::string_view text) {
  std::size_t start = 0;
  while (start <= text.size() && errors_ < kMaxErrors) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    ++line_;
    const std::vector<Token> tokens = tokenize(text.substr(start, end - start));
    if (!tokens.empty()) statement(tokens);
    start = end + 1;
  }
  if (errors_ >= kMaxErrors) {
    diagnostics_.back().notes.push_back("too many errors; reading stopped at line " +
                                        std::to_string(line_));
  }
  if (errors_ == 0 && model_.mesh.face_count() == 0) {
    // faces_ counts the dropped faces too (it numbers the file's faces).
    diagnostics_.push_back(Diagnostic::error(
        "OBJ007",
        faces_ == 0 ? "the file has no faces" : "the file has no face with 3 distinct vertices",
        Span::whole(source_)));
    ++errors_;
  }
  if (errors_ > 0) return base::Result<ObjModel>::failure(std::move(diagnostics_));
  return base::Result<ObjModel>(std::move(model_), std::move(diagnostics_));
}

void Parser::statement(const std::vector<Token>& tokens) {
  const std::string_view keyword = tokens.front().text;
  if (keyword == "v") return vertex(tokens);
  if (keyword == "f") return face(tokens);
  if (keyword == "usemtl") return use_material(tokens);
  if (keyword == "g") {
    group_semantic_ = kernel::SemanticClass::kNone;
    for (std::size_t i = 1; i < tokens.size(); ++i) {
      const kernel::SemanticClass semantic = semantic_of(tokens[i].text);
      if (semantic != kernel::SemanticClass::kNone) group_semantic_ = semantic;
    }
    return;
  }
  for (std::string_view ignored : {"vt", "vn", "vp", "s", "l", "p", "o", "mtllib"}) {
    if (keyword == ignored) return;
  }
  warning("OBJ100", "unsupported statement " + quoted(keyword) + " ignored", tokens.front());
}

void Parser::vertex(const std::vector<Token>& tokens) {
  // x y z, optionally w (rational curves) or r g b (a common vertex-colour extension).
  const std::size_t count = tokens.size() - 1;
  if (count != 3 && count != 4 && count != 6 && count != 7) {
    error("OBJ001", "a vertex needs 3 coordinates, found " + std::to_string(count), tokens.front());
    return;
  }
  double xyz[3] = {0, 0, 0};
  for (std::size_t i = 1; i < tokens.size(); ++i) {
    const std::optional<double> value = parse_double(tokens[i].text);
    if (!value) return error("OBJ002", quoted(tokens[i].text) + " is not a number", tokens[i]);
    if (!std::isfinite(*value)) {
      return error("OBJ003", "coordinate " + quoted(tokens[i].text) + " is not finite", tokens[i]);
    }
    if (i <= 3) xyz[i - 1] = *value;
  }
  model_.mesh.add_vertex({xyz[0], xyz[1], xyz[2]});
}

std::optional<std::uint32_t> Parser::vertex_reference(const Token& token) {
  const std::string_view text = token.text;
  const std::size_t slash = text.find('/');
  long long index = 0;
  const IntStatus status = parse_int(text.substr(0, slash), index);
  if (status == IntStatus::kNotANumber) {
    error("OBJ006", quoted(text) + " is not a vertex reference", token);
    return std::nullopt;
  }
  // The texture and normal parts are ignored, but must be numbers when present.
  if (slash != std::string_view::npos) {
    std::string_view rest = text.substr(slash + 1);
    for (std::size_t part = 0; part < 2 && !rest.empty(); ++part) {
      const std::size_t next = rest.find('/');
      long long ignored = 0;
      const std::string_view piece = rest.substr(0, next);
      if ((!piece.empty() && parse_int(piece, ignored) == IntStatus::kNotANumber) ||
          (part == 1 && next != std::string_view::npos)) {
        error("OBJ006", quoted(text) + " is not a vertex reference", token);
        return std::nullopt;
      }
      rest = next == std::string_view::npos ? std::string_view() : rest.substr(next + 1);
    }
  }
  const auto defined = static_cast<long long>(model_.mesh.vertex_count());
  if (status == IntStatus::kOk && index == 0) {
    error("OBJ005", "vertex index 0 is invalid (OBJ indices start at 1)", token);
    return std::nullopt;
  }
  const long long resolved = index < 0 ? defined + index : index - 1;
  if (status == IntStatus::kOutOfRange || resolved < 0 || resolved >= defined) {
    error("OBJ005",
          "vertex index " + std::string(text.substr(0, slash)) + " is out of range (" +
              std::to_string(defined) + " vertices defined so far)",
          token);
    return std::nullopt;
  }
  return static_cast<std::uint32_t>(resolved);
}

void Parser::face(const std::vector<Token>& tokens) {
  if (tokens.size() < 4) {
    error("OBJ004", "a face needs at least 3 vertices, found " + std::to_string(tokens.size() - 1),
          tokens.front());
    return;
  }
  std::vector<std::uint32_t> loop;
  bool ok = true;
  for (std::size_t i = 1; i < tokens.size(); ++i) {
    const std::optional<std::uint32_t> vertex = vertex_reference(tokens[i]);
    if (!vertex) ok = false;
    if (ok && (loop.empty() || loop.back() != *vertex)) loop.push_back(*vertex);
  }
  if (!ok) return;
  while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
  const std::uint32_t id = faces_++;
  if (loop.size() < 3) {
    warning("OBJ101", "face repeats its vertices and has fewer than 3 distinct ones; dropped",
            tokens.front());
    return;
  }
  const kernel::SemanticClass semantic =
      group_semantic_ != kernel::SemanticClass::kNone ? group_semantic_ : material_semantic_;
  model_.mesh.add_face(loop, {semantic, material_, id});
}

void Parser::use_material(const std::vector<Token>& tokens) {
  if (tokens.size() < 2) {
    warning("OBJ102", "usemtl without a material name ignored", tokens.front());
    return;
  }
  const std::string_view name = tokens[1].text;
  material_semantic_ = semantic_of(name);
  for (std::size_t i = 0; i < model_.materials.size(); ++i) {
    if (model_.materials[i] == name) {
      material_ = static_cast<kernel::MaterialId>(i + 1);
      return;
    }
  }
  if (model_.materials.size() >= 65534) {
    warning("OBJ103", "too many materials; " + quoted(name) + " ignored", tokens[1]);
    material_ = 0;
    return;
  }
  model_.materials.emplace_back(name);
  material_ = static_cast<kernel::MaterialId>(model_.materials.size());
}

}  // namespace

base::Result<ObjModel> parse_obj(std::string_view text, const std::string& source_name) {
  return Parser(source_name).run(text);
}

base::Result<kernel::Mesh> read_obj(std::string_view text, const std::string& source_name) {
  base::Result<ObjModel> model = parse_obj(text, source_name);
  if (!model) return base::Result<kernel::Mesh>::failure(std::move(model.diagnostics()));
  return base::Result<kernel::Mesh>(std::move(model->mesh), std::move(model.diagnostics()));
}

}  // namespace insula::io
