#include "base/diagnostic.h"

#include <algorithm>

namespace insula::base {

Source::Source(std::string name, std::string text)
    : name_(std::move(name)), text_(std::move(text)) {
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text_.size(); ++i) {
    if (text_[i] == '\n') line_starts_.push_back(i + 1);
  }
}

std::pair<std::uint32_t, std::uint32_t> Source::locate(std::size_t offset) const {
  offset = std::min(offset, text_.size());
  auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const std::size_t index = static_cast<std::size_t>(it - line_starts_.begin()) - 1;
  const std::size_t first = parts_.empty() ? 0 : part_at(offset).first_line;
  return {static_cast<std::uint32_t>(index - first + 1),
          static_cast<std::uint32_t>(offset - line_starts_[index] + 1)};
}

std::size_t Source::append(std::string name, std::string_view text) {
  if (parts_.empty()) parts_.push_back({name_, 0, 0});
  if (!text_.empty() && text_.back() != '\n') {
    text_ += '\n';
    line_starts_.push_back(text_.size());
  }
  const std::size_t begin = text_.size();
  parts_.push_back({std::move(name), begin, line_starts_.size() - 1});
  text_.append(text);
  for (std::size_t i = begin; i < text_.size(); ++i) {
    if (text_[i] == '\n') line_starts_.push_back(i + 1);
  }
  return begin;
}

const Source::Part& Source::part_at(std::size_t offset) const {
  auto it = std::upper_bound(parts_.begin(), parts_.end(), offset,
                             [](std::size_t o, const Part& p) { return o < p.begin; });
  return *(it - 1);
}

const std::string& Source::name_at(std::size_t offset) const {
  return parts_.empty() ? name_ : part_at(std::min(offset, text_.size())).name;
}

std::string_view Source::line_of(const std::string& file, std::uint32_t line) const {
  if (parts_.empty()) return this->line(line);  // one file: whatever name the span gives
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    if (parts_[k].name != file) continue;
    const std::size_t last = k + 1 < parts_.size() ? parts_[k + 1].first_line : line_starts_.size();
    if (line == 0 || parts_[k].first_line + line > last) return {};
    return this->line(static_cast<std::uint32_t>(parts_[k].first_line + line));
  }
  return {};
}

std::string_view Source::line(std::uint32_t line) const {
  if (line == 0 || line > line_starts_.size()) return {};
  const std::size_t begin = line_starts_[line - 1];
  std::size_t end = line < line_starts_.size() ? line_starts_[line] : text_.size();
  while (end > begin && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
  return std::string_view(text_).substr(begin, end - begin);
}

Span Span::at(std::string file, std::uint32_t line, std::uint32_t column, std::uint32_t length) {
  return Span{std::move(file), line, column, line, column + std::max<std::uint32_t>(length, 1)};
}

Diagnostic Diagnostic::error(std::string code, std::string message, Span span) {
  return Diagnostic{Severity::kError, std::move(code), std::move(message), std::move(span), {}};
}

Diagnostic Diagnostic::warning(std::string code, std::string message, Span span) {
  return Diagnostic{Severity::kWarning, std::move(code), std::move(message), std::move(span), {}};
}

std::string_view severity_name(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return "error";
    case Severity::kWarning:
      return "warning";
    case Severity::kNote:
      return "note";
  }
  return "error";
}

namespace {

std::string location_prefix(const Span& span) {
  std::string out = span.file.empty() ? std::string("<input>") : span.file;
  if (span.line > 0) {
    out += ':';
    out += std::to_string(span.line);
    out += ':';
    out += std::to_string(std::max<std::uint32_t>(span.column, 1));
  }
  return out;
}

// The source line and a caret (with tildes across the span on that line).
// Lines longer than this are shown as a window around the column (minified JSON is one long line).
constexpr std::size_t kMaxShownLine = 160;
constexpr std::size_t kContextBefore = 60;

// The source line and a caret (with tildes across the span on that line).
std::string caret_lines(const Span& span, const Source& source) {
  std::string_view text = source.line_of(span.file, span.line);
  if (text.empty() && span.line > 1) return {};
  std::size_t column = std::max<std::uint32_t>(span.column, 1);
  std::size_t end_column = span.end_line == span.line ? span.end_column : 0;
  std::string prefix;
  if (text.size() > kMaxShownLine) {
    const std::size_t first = column > kContextBefore ? column - 1 - kContextBefore : 0;
    text = text.substr(first, kMaxShownLine);
    if (first > 0) prefix = "...";
    column = column - first + prefix.size();
    end_column = end_column > first ? end_column - first + prefix.size() : 0;
  }
  std::string marker(column - 1, ' ');
  for (std::size_t i = prefix.size(); i + 1 < column && i - prefix.size() < text.size(); ++i) {
    if (text[i - prefix.size()] == '\t') marker[i] = '\t';
  }
  marker += '^';
  const std::size_t shown = prefix.size() + text.size();
  for (std::size_t c = column; c + 1 < std::min(end_column, shown + 1); ++c) marker += '~';
  std::string out(1, '\n');
  out += prefix;
  out.append(text);
  out += '\n';
  out += marker;
  return out;
}

}  // namespace

std::string render(const Diagnostic& diagnostic, const Source* source) {
  std::string out = location_prefix(diagnostic.span) + ": ";
  out += severity_name(diagnostic.severity);
  if (!diagnostic.code.empty()) {
    out += '[';
    out += diagnostic.code;
    out += ']';
  }
  out += ": ";
  out += diagnostic.message;
  if (source != nullptr && diagnostic.span.line > 0) out += caret_lines(diagnostic.span, *source);
  for (const std::string& note : diagnostic.notes) {
    out += "\nnote: ";
    out += note;
  }
  return out;
}

bool has_errors(const std::vector<Diagnostic>& diagnostics) {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::kError; });
}

}  // namespace insula::base
