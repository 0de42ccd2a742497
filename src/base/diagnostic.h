// Diagnostics shared by every reader and language: `file:line:col: error[CODE]: message`, a caret
// line under the offending source text, and notes. Readers return diagnostics and never print.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace insula::base {

// A named text (a file's contents) with a line index, so byte offsets become line and column.
class Source {
 public:
  Source(std::string name, std::string text);

  const std::string& name() const { return name_; }
  const std::string& text() const { return text_; }
  // 1-based line and column (column counts bytes) of a byte offset; offsets past the end clamp.
  // In a source with appended files, the line counts from the start of the offset's file.
  std::pair<std::uint32_t, std::uint32_t> locate(std::size_t offset) const;
  // The text of a 1-based line without its line break; empty when out of range.
  std::string_view line(std::uint32_t line) const;

  // A source of several files (a CGA rule file and the files it imports): `text` is appended
  // after a line break and positions in it are reported in file `name`. Returns the offset of its
  // first byte.
  std::size_t append(std::string name, std::string_view text);
  // The file holding byte `offset` (name() when nothing was appended).
  const std::string& name_at(std::size_t offset) const;
  // Line `line` (1-based) of file `file`; empty when out of range or no such file.
  std::string_view line_of(const std::string& file, std::uint32_t line) const;

 private:
  struct Part {
    std::string name;
    std::size_t begin = 0;       // byte offset of the file's first byte
    std::size_t first_line = 0;  // index into line_starts_ of its first line
  };
  const Part& part_at(std::size_t offset) const;

  std::string name_;
  std::string text_;
  std::vector<std::size_t> line_starts_;
  std::vector<Part> parts_;  // empty: one file
};

// A range in a named file; line 0 means "the whole file" (no position known).
struct Span {
  std::string file;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::uint32_t end_line = 0;
  std::uint32_t end_column = 0;

  static Span at(std::string file, std::uint32_t line, std::uint32_t column,
                 std::uint32_t length = 1);
  static Span whole(std::string file) { return Span{std::move(file)}; }
};

enum class Severity { kError, kWarning, kNote };

struct Diagnostic {
  Severity severity = Severity::kError;
  std::string code;  // stable identifier such as "GEO004"; may be empty
  std::string message;
  Span span;
  std::vector<std::string> notes;

  static Diagnostic error(std::string code, std::string message, Span span);
  static Diagnostic warning(std::string code, std::string message, Span span);
};

std::string_view severity_name(Severity severity);

// `file:line:col: error[CODE]: message`, then the source line and a caret line when `source` is
// given and the span has a position, then one `note: ...` line per note. Ends without a newline.
std::string render(const Diagnostic& diagnostic, const Source* source = nullptr);

bool has_errors(const std::vector<Diagnostic>& diagnostics);

// A value or the diagnostics that explain why there is none; warnings may accompany a value.
template <typename T>
class Result {
 public:
  Result(T value, std::vector<Diagnostic> diagnostics = {})
      : value_(std::move(value)), diagnostics_(std::move(diagnostics)) {}
  static Result failure(std::vector<Diagnostic> diagnostics) {
    Result r;
    r.diagnostics_ = std::move(diagnostics);
    return r;
  }

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  T& value() { return *value_; }
  const T& value() const { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  std::vector<Diagnostic>& diagnostics() { return diagnostics_; }

 private:
  Result() = default;
  std::optional<T> value_;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace insula::base
