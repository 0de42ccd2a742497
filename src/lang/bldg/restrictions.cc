// Restriction rules (seed 000, §3.3): "a related value specifying a growth factor is used as a
// reference from the restriction rules to guide the distribution process (e.g., small, medium,
// and big rooms grow with a rate of 1.5, 2, and 2.5, respectively, regarding a fixed value such
// as 0.001)"; door width "a percentage of the building's layout perimeter"; borrowing limits
// (Fig. 4); the scaling step of Eq. 5 ("0.01 or 0.001, specifiable in the restriction rules");
// and Table 3's "default parameters defining building components' textures and dimensions".
//
//   file  = { entry | ";" } EOF ;
//   entry = IDENT { "." IDENT } "=" ( [ "-" ] NUMBER | STRING | "(" number_list ")" ) [ ";" ] ;
#include "lang/bldg/restrictions.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "kernel/semantic.h"
#include "lang/bldg/lexer.h"

namespace insula::lang::bldg {
namespace {

struct Key {
  const char* name;
  double& (*field)(Restrictions&);
  double min;
  double max;
  bool min_open;  // (min, ...] instead of [min, ...]
};

// clang-format off
const Key kKeys[] = {
    {"initial_weight", [](Restrictions& r) -> double& { return r.initial_weight; }, 0, 0.1, true},
    {"growth.small", [](Restrictions& r) -> double& { return r.growth[0]; }, 1, 100, true},
    {"growth.medium", [](Restrictions& r) -> double& { return r.growth[1]; }, 1, 100, true},
    {"growth.big", [](Restrictions& r) -> double& { return r.growth[2]; }, 1, 100, true},
    {"step", [](Restrictions& r) -> double& { return r.step; }, 0, 0.5, true},
    {"door_width", [](Restrictions& r) -> double& { return r.door_width; }, 0.3, 5, false},
    {"entrance_width", [](Restrictions& r) -> double& { return r.entrance_width; }, 0.3, 5, false},
    {"door_width_fraction", [](Restrictions& r) -> double& { return r.door_width_fraction; }, 0, 0.5, false},
    {"door_min_width", [](Restrictions& r) -> double& { return r.door_min_width; }, 0.3, 5, false},
    {"door_height", [](Restrictions& r) -> double& { return r.door_height; }, 1, 10, false},
    {"borrow_limit", [](Restrictions& r) -> double& { return r.borrow_limit; }, 0, 0.9, false},
    {"min_room_area", [](Restrictions& r) -> double& { return r.min_room_area; }, 0, 100, false},
    {"min_room_width", [](Restrictions& r) -> double& { return r.min_room_width; }, 0, 10, false},
    {"outer_wall_thickness", [](Restrictions& r) -> double& { return r.outer_wall_thickness; }, 0, 2, true},
    {"inner_wall_thickness", [](Restrictions& r) -> double& { return r.inner_wall_thickness; }, 0, 2, true},
    {"storey_height", [](Restrictions& r) -> double& { return r.storey_height; }, 2, 20, false},
    {"window_width", [](Restrictions& r) -> double& { return r.window_width; }, 0, 10, true},
    {"window_height", [](Restrictions& r) -> double& { return r.window_height; }, 0, 10, true},
    {"window_sill", [](Restrictions& r) -> double& { return r.window_sill; }, 0, 10, false},
    {"base_height", [](Restrictions& r) -> double& { return r.base_height; }, 0, 5, false},
    {"footer_height", [](Restrictions& r) -> double& { return r.footer_height; }, 0, 1, false},
    {"stair_width", [](Restrictions& r) -> double& { return r.stair_width; }, 0.5, 5, false},
};
// clang-format on

std::string format(double v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : "0";
}

struct Abort {};

class RulesParser {
 public:
  explicit RulesParser(const base::Source& source) : source_(source) {
    LexOutput lexed = lex(source);
    tokens_ = std::move(lexed.tokens);
    diags_ = std::move(lexed.diagnostics);
  }

  base::Result<Restrictions> run() {
    while (!at(Tok::kEnd) && diags_.size() <= 50) {
      if (accept(Tok::kSemicolon)) continue;
      const std::size_t start = pos_;
      try {
        entry();
      } catch (const Abort&) {
        if (pos_ == start) advance();
        while (!at(Tok::kEnd) && !peek().line_start) advance();
      }
    }
    check_consistency();
    if (base::has_errors(diags_)) return base::Result<Restrictions>::failure(std::move(diags_));
    return base::Result<Restrictions>(std::move(rules_), std::move(diags_));
  }

 private:
  const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  bool at(Tok kind) const { return peek().kind == kind; }
  const Token& advance() {
    const Token& token = peek();
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return token;
  }
  bool accept(Tok kind) {
    if (!at(kind)) return false;
    advance();
    return true;
  }
  void error(const char* code, std::string message, Range range) {
    diags_.push_back(base::Diagnostic::error(code, std::move(message), span_of(source_, range)));
  }
  [[noreturn]] void fail(const char* code, std::string message, Range range) {
    error(code, std::move(message), range);
    throw Abort{};
  }
  [[noreturn]] void fail_here(const std::string& expected) {
    fail("BLD101", "expected " + expected + ", found " + describe(peek()), peek().range);
  }

  void entry() {
    if (!at(Tok::kIdent)) fail_here("a restriction key (e.g. 'storey_height')");
    const Range key_range_begin = peek().range;
    std::string key = advance().text;
    while (accept(Tok::kDot)) {
      if (!at(Tok::kIdent)) fail_here("a name after '.' in the key");
      key += "." + advance().text;
    }
    const Range key_range{key_range_begin.begin, tokens_[pos_ - 1].range.end};
    if (!accept(Tok::kAssign)) fail_here("'=' after the key '" + key + "'");
    if (key.rfind("color.", 0) == 0) return color_entry(key, key_range);
    const Key* spec = nullptr;
    for (const Key& k : kKeys) {
      if (key == k.name) spec = &k;
    }
    if (spec == nullptr) {
      error("BLD301", "unknown restriction key '" + key + "'", key_range);
      skip_value();
      return;
    }
    const Range value_range = peek().range;
    const std::optional<double> value = signed_number();
    if (!value)
      fail("BLD302", "'" + key + "' expects a number, found " + describe(peek()), peek().range);
    const Range range{value_range.begin, tokens_[pos_ - 1].range.end};
    accept(Tok::kSemicolon);
    if (!given_.emplace(key, range).second) {
      error("BLD304", "restriction key '" + key + "' is given twice", key_range);
      return;
    }
    const bool low = spec->min_open ? *value <= spec->min : *value < spec->min;
    if (low || *value > spec->max) {
      error("BLD303",
            "'" + key + "' = " + format(*value) + " is out of range " +
                (spec->min_open ? "(" : "[") + format(spec->min) + ", " + format(spec->max) + "]",
            range);
      return;
    }
    spec->field(rules_) = *value;
  }

  std::optional<double> signed_number() {
    const bool negative = at(Tok::kMinus);
    if (negative && peek(1).kind != Tok::kNumber) return std::nullopt;
    if (!negative && !at(Tok::kNumber)) return std::nullopt;
    if (negative) advance();
    const double v = advance().number;
    return negative ? -v : v;
  }

  void skip_value() {
    while (!at(Tok::kEnd) && !peek().line_start && !at(Tok::kSemicolon)) advance();
    accept(Tok::kSemicolon);
  }

  void color_entry(const std::string& key, Range key_range) {
    const std::string name = key.substr(6);
    const auto semantic = kernel::semantic_from_name(name);
    if (!semantic || *semantic == kernel::SemanticClass::kNone) {
      error("BLD301",
            "unknown semantic class '" + name +
                "' in a colour key (WallSurface, RoofSurface, FloorSurface, Door, Window, ...)",
            key_range);
      skip_value();
      return;
    }
    const Range value_range = peek().range;
    std::array<float, 4> rgba{0, 0, 0, 1};
    if (at(Tok::kString)) {
      if (!hex_color(peek().text, rgba)) {
        fail("BLD302",
             "'" + key + "' expects a colour \"#rrggbb\" or \"#rrggbbaa\", found " +
                 describe(peek()),
             peek().range);
      }
      advance();
    } else if (accept(Tok::kLParen)) {
      tuple_color(key, rgba);
    } else {
      fail("BLD302",
           "'" + key + "' expects a colour (\"#rrggbb\" or (r, g, b[, a])), found " +
               describe(peek()),
           peek().range);
    }
    accept(Tok::kSemicolon);
    if (!given_.emplace(key, value_range).second) {
      error("BLD304", "restriction key '" + key + "' is given twice", key_range);
      return;
    }
    rules_.colors.emplace_back(name, rgba);
  }

  void tuple_color(const std::string& key, std::array<float, 4>& rgba) {
    std::size_t n = 0;
    while (true) {
      const Range range = peek().range;
      const std::optional<double> v = signed_number();
      if (!v) fail_here("a colour component in [0, 1]");
      if (*v < 0 || *v > 1) {
        fail("BLD303", "colour component " + format(*v) + " of '" + key + "' is out of [0, 1]",
             range);
      }
      if (n >= 4) fail("BLD302", "'" + key + "' has more than 4 colour components", range);
      rgba[n++] = static_cast<float>(*v);
      if (accept(Tok::kComma)) continue;
      if (!at(Tok::kRParen)) fail_here("',' or ')' in the colour");
      if (n < 3) fail("BLD302", "'" + key + "' needs 3 or 4 colour components", peek().range);
      advance();
      return;
    }
  }

  static bool hex_color(const std::string& text, std::array<float, 4>& rgba) {
    if ((text.size() != 7 && text.size() != 9) || text[0] != '#') return false;
    for (std::size_t i = 1; i < text.size(); i += 2) {
      unsigned value = 0;
      const auto [ptr, ec] = std::from_chars(text.data() + i, text.data() + i + 2, value, 16);
      if (ec != std::errc() || ptr != text.data() + i + 2) return false;
      rgba[(i - 1) / 2] = static_cast<float>(value) / 255.0F;
    }
    return true;
  }

  // Openings must fit under the storey (a 2.1 m door in a 2 m storey cuts the ceiling).
  void check_consistency() {
    if (base::has_errors(diags_)) return;
    if (rules_.door_height >= rules_.storey_height) {
      error("BLD305",
            "door_height " + format(rules_.door_height) + " must be below storey_height " +
                format(rules_.storey_height),
            later("door_height", "storey_height"));
    }
    if (rules_.window_sill + rules_.window_height >= rules_.storey_height) {
      error("BLD305",
            "window_sill + window_height = " + format(rules_.window_sill + rules_.window_height) +
                " must be below storey_height " + format(rules_.storey_height),
            later("window_height", later_key("window_sill", "storey_height")));
    }
  }

  std::string later_key(const std::string& a, const std::string& b) const {
    const auto ia = given_.find(a), ib = given_.find(b);
    if (ia == given_.end()) return b;
    if (ib == given_.end()) return a;
    return ia->second.begin > ib->second.begin ? a : b;
  }
  Range later(const std::string& a, const std::string& b) const {
    const std::string key = later_key(a, b);
    const auto it = given_.find(key);
    return it == given_.end() ? Range{0, 0} : it->second;
  }

  const base::Source& source_;
  std::vector<Token> tokens_;
  std::vector<base::Diagnostic> diags_;
  std::size_t pos_ = 0;
  Restrictions rules_;
  std::map<std::string, Range> given_;  // key -> value range
};

}  // namespace

base::Result<Restrictions> parse_restrictions(const base::Source& source) {
  return RulesParser(source).run();
}

std::string print_restrictions(const Restrictions& restrictions) {
  Restrictions copy = restrictions;
  std::string out = "# Insula restriction rules (seed 000, §3.3)\n";
  for (const Key& key : kKeys) {
    out += std::string(key.name) + " = " + format(key.field(copy)) + "\n";
  }
  for (const auto& [name, rgba] : restrictions.colors) {
    out += "color." + name + " = (" + format(rgba[0]) + ", " + format(rgba[1]) + ", " +
           format(rgba[2]) + ", " + format(rgba[3]) + ")\n";
  }
  return out;
}

}  // namespace insula::lang::bldg
