#include "lang/cga/json_out.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "lang/cga/printer.h"
#include "lang/cga/xml_text.h"

namespace insula::lang::cga {

void JsonOut::newline() {
  out_ += '\n';
  out_.append(has_items_.size() * 2, ' ');
}

void JsonOut::before_value() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (has_items_.empty()) return;
  if (has_items_.back()) out_ += ',';
  has_items_.back() = true;
  newline();
}

void JsonOut::open(char bracket) {
  before_value();
  out_ += bracket;
  has_items_.push_back(false);
}

void JsonOut::close(char bracket) {
  const bool items = has_items_.back();
  has_items_.pop_back();
  if (items) newline();
  out_ += bracket;
}

void JsonOut::key(std::string_view name) {
  before_value();
  quoted(name);
  out_ += ": ";
  after_key_ = true;
}

void JsonOut::string(std::string_view text) {
  before_value();
  quoted(text);
}

void JsonOut::quoted(std::string_view text) {
  out_ += '"';
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x80) {
      const std::size_t length = utf8_length(text, i);
      if (length == 0) {
        out_ += "\xEF\xBF\xBD";
        ++i;
      } else {
        out_.append(text.substr(i, length));
        i += length;
      }
      continue;
    }
    ++i;
    switch (c) {
      case '"':
        out_ += "\\\"";
        break;
      case '\\':
        out_ += "\\\\";
        break;
      case '\n':
        out_ += "\\n";
        break;
      case '\t':
        out_ += "\\t";
        break;
      case '\r':
        out_ += "\\r";
        break;
      default:
        if (byte < 0x20) {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", byte);
          out_ += buffer;
        } else {
          out_ += c;
        }
    }
  }
  out_ += '"';
}

void JsonOut::number(double value) {
  if (!std::isfinite(value)) return null();
  scalar(number_text(value));
}

void JsonOut::integer(long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  scalar(std::string_view(buffer, static_cast<std::size_t>(result.ptr - buffer)));
}

void JsonOut::inline_object(std::initializer_list<std::pair<std::string_view, long long>> members) {
  before_value();
  out_ += '{';
  bool first = true;
  for (const auto& [name, value] : members) {
    if (!first) out_ += ", ";
    first = false;
    out_ += '"';
    out_ += name;
    out_ += "\": ";
    out_ += std::to_string(value);
  }
  out_ += '}';
}

std::string JsonOut::take() {
  out_ += '\n';
  has_items_.clear();
  after_key_ = false;
  return std::move(out_);
}

}  // namespace insula::lang::cga
