// A small streaming JSON writer for the model and graph exports: a grammar of a few MB becomes a
// JSON text of a hundred MB, which a DOM (nlohmann) builds and copies at several times the cost
// (docs/PERFORMANCE.md). Objects and arrays are indented by two spaces; `inline_object`
// writes a small object on one line (source ranges). Strings are escaped per RFC 8259 and
// invalid UTF-8 is replaced by U+FFFD, so any parsed grammar gives valid JSON.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace insula::lang::cga {

class JsonOut {
 public:
  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }
  // Starts a member of the current object; the value follows.
  void key(std::string_view name);

  void string(std::string_view text);
  void number(double value);  // null when not finite
  void integer(long long value);
  void boolean(bool value) { scalar(value ? "true" : "false"); }
  void null() { scalar("null"); }
  // `{"a": 1, "b": 2}` on one line, from name/value pairs.
  void inline_object(std::initializer_list<std::pair<std::string_view, long long>> members);

  // The text, ending with a newline. The writer is empty afterwards.
  std::string take();

 private:
  void open(char bracket);
  void close(char bracket);
  void before_value();
  void scalar(std::string_view text) {
    before_value();
    out_ += text;
  }
  void newline();
  void quoted(std::string_view text);  // the escaped string literal, nothing before it

  std::string out_;
  std::vector<bool> has_items_;  // per open container
  bool after_key_ = false;
};

}  // namespace insula::lang::cga
