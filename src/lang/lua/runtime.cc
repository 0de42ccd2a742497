// The sandboxed Lua state: libraries, limits, and the translation of Lua errors into diagnostics.
// Lua is a C library that reports errors by longjmp; no C++ object with a destructor is alive in
// the frames below (bindings go through protect<>, binding.h).
#include "lang/lua/runtime.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "lang/lua/binding.h"
#include "lang/lua/bindings_internal.h"
#include "shape/collect.h"

namespace insula::lua {

// Allocator and hook state of one state. Kept apart from Program (binding.h) because the allocator
// outlives the program's tree while lua_close runs.
struct Runtime::Guard {
  Limits limits;
  Program* program = nullptr;
  lua_State* L = nullptr;
  std::size_t used = 0;
  std::size_t peak = 0;
  std::uint64_t count_events = 0;
  int depth = 0;
  int memory_line = 0;    // the Lua line running when the heap cap was hit
  std::string short_src;  // the main chunk's name as Lua prints it
  std::string source;     // the main chunk's full source name ("=file")
};

namespace {

// Instructions between two count-hook calls: small enough for a prompt stop and a useful count in
// the report of a small program (issue 12 item 11: 1000 reported 0 for most examples); any count
// hook already makes the VM check every instruction, so calling the hook more often costs little.
constexpr int kHookInterval = 100;

Runtime::Guard*& guard_slot(Program& p) {
  return *reinterpret_cast<Runtime::Guard**>(&p.runtime);
}

Runtime::Guard& guard(lua_State* L) {
  return *guard_slot(program(L));
}

// The first Lua frame at or above `level`: its current line (0 when none).
int lua_line(lua_State* L, int level, const std::string* only_source = nullptr) {
  lua_Debug ar;
  for (; lua_getstack(L, level, &ar) != 0; ++level) {
    if (lua_getinfo(L, "Sl", &ar) == 0 || ar.currentline <= 0) continue;
    if (only_source != nullptr && *only_source != ar.source) continue;
    return ar.currentline;
  }
  return 0;
}

void* allocate(void* ud, void* ptr, std::size_t osize, std::size_t nsize) {
  auto* g = static_cast<Runtime::Guard*>(ud);
  const std::size_t old = ptr != nullptr ? osize : 0;
  if (nsize == 0) {
    g->used -= old;
    std::free(ptr);
    return nullptr;
  }
  if (nsize > old && g->used + (nsize - old) > g->limits.memory_bytes) {
    // Lua turns a null into a memory error (after an emergency collection). Remember where the
    // program was: the error reaches the top without a message handler.
    if (g->L != nullptr && g->memory_line == 0) g->memory_line = lua_line(g->L, 0, &g->source);
    return nullptr;
  }
  void* out = std::realloc(ptr, nsize);
  if (out == nullptr) return nullptr;
  g->used = g->used - old + nsize;
  g->peak = std::max(g->peak, g->used);
  return out;
}

// Stops the program for good: the message is located at the running Lua line and kept, so a
// pcall that catches it re-raises it (safe_pcall). Recording and raising are two calls because
// lua_error unwinds with longjmp: a C++ temporary alive at the raise (the caller's message) would
// never be destroyed, so the caller's message must be gone before raise_stop runs.
void record_stop(lua_State* L, const std::string& what, int line) {
  Program& p = program(L);
  if (!p.stopped) {
    p.stopped = true;
    p.stop_message = guard(L).short_src + ":" + std::to_string(line) + ": " + what;
  }
}

[[noreturn]] void raise_stop(lua_State* L) {
  const Program& p = program(L);
  lua_pushlstring(L, p.stop_message.data(), p.stop_message.size());
  lua_error(L);
  std::abort();  // lua_error does not return
}

std::string limit_text(const char* what, std::uint64_t value, const char* unit = "") {
  return std::string(what) + " limit of " + std::to_string(value) + unit + " reached";
}

void hook(lua_State* L, lua_Debug* ar) {
  Runtime::Guard& g = guard(L);
  switch (ar->event) {
    case LUA_HOOKCOUNT:
      if (++g.count_events * kHookInterval > g.limits.instructions) {
        record_stop(L, limit_text("instruction", g.limits.instructions), lua_line(L, 0));
        raise_stop(L);
      }
      break;
    case LUA_HOOKCALL:
      if (++g.depth > g.limits.call_depth) {
        record_stop(L, limit_text("call depth", static_cast<std::uint64_t>(g.limits.call_depth)),
                    lua_line(L, 1));
        raise_stop(L);
      }
      break;
    case LUA_HOOKRET:
      --g.depth;
      break;
    default:  // a tail call replaces a frame: the depth is unchanged
      break;
  }
}

// pcall / xpcall that cannot swallow a limit: after a stop, or a memory error (the heap cap), the
// error is raised again.
int finish_pcall(lua_State* L, int status, int depth, int base) {
  Runtime::Guard& g = guard(L);
  Program& p = program(L);
  g.depth = depth;  // frames unwound by the error sent no return events
  if (status == LUA_ERRMEM && !p.stopped) {
    p.stopped = true;
    p.stop_message = g.short_src + ":" + std::to_string(g.memory_line) + ": " +
                     limit_text("memory", g.limits.memory_bytes >> 20, " MB");
  }
  if (p.stopped) {
    lua_pushlstring(L, p.stop_message.data(), p.stop_message.size());
    return lua_error(L);
  }
  if (status != LUA_OK) {
    lua_pushboolean(L, 0);
    lua_insert(L, -2);
    return 2;
  }
  lua_pushboolean(L, 1);
  lua_insert(L, base);
  return lua_gettop(L) - base + 1;
}

int safe_pcall(lua_State* L) {
  luaL_checkany(L, 1);
  const int depth = guard(L).depth;
  const int status = lua_pcall(L, lua_gettop(L) - 1, LUA_MULTRET, 0);
  return finish_pcall(L, status, depth, 1);
}

int safe_xpcall(lua_State* L) {
  const int n = lua_gettop(L);
  luaL_checktype(L, 2, LUA_TFUNCTION);
  lua_pushvalue(L, 1);  // f
  lua_copy(L, 2, 1);    // handler at 1
  lua_replace(L, 2);    // f at 2
  const int depth = guard(L).depth;
  const int status = lua_pcall(L, n - 2, LUA_MULTRET, 1);
  return finish_pcall(L, status, depth, 2);
}

// load(chunk [, name [, mode [, env]]]) with text chunks only.
int safe_load(lua_State* L) {
  const int n = lua_gettop(L);
  if (n >= 3 && !lua_isnil(L, 3)) {
    const char* mode = luaL_checkstring(L, 3);
    if (std::strchr(mode, 'b') != nullptr) {
      return luaL_error(L, "load: binary chunks are not allowed (mode 't' only)");
    }
  }
  lua_getfield(L, lua_upvalueindex(1), "load");  // the original load
  lua_pushvalue(L, 1);
  if (n >= 2) {
    lua_pushvalue(L, 2);
  } else {
    lua_pushnil(L);
  }
  lua_pushliteral(L, "t");
  if (n >= 4) {
    lua_pushvalue(L, 4);
    lua_call(L, 4, LUA_MULTRET);
  } else {
    lua_call(L, 3, LUA_MULTRET);
  }
  return lua_gettop(L) - n;
}

// collectgarbage with the options that cannot defeat the limits.
int safe_collectgarbage(lua_State* L) {
  const char* option = luaL_optstring(L, 1, "collect");
  if (std::strcmp(option, "collect") == 0) {
    lua_gc(L, LUA_GCCOLLECT);
    lua_pushinteger(L, 0);
    return 1;
  }
  if (std::strcmp(option, "count") == 0) {
    const int kb = lua_gc(L, LUA_GCCOUNT);
    const int rest = lua_gc(L, LUA_GCCOUNTB);
    lua_pushnumber(L, kb + rest / 1024.0);
    return 1;
  }
  if (std::strcmp(option, "step") == 0) {
    lua_pushboolean(L, lua_gc(L, LUA_GCSTEP, 0));
    return 1;
  }
  return luaL_error(L, "collectgarbage: option '%s' is not allowed (collect, count, step)", option);
}

int safe_print(lua_State* L) {
  const int n = lua_gettop(L);
  luaL_Buffer b;
  luaL_buffinit(L, &b);
  for (int i = 1; i <= n; ++i) {
    if (i > 1) luaL_addchar(&b, '\t');
    luaL_tolstring(L, i, nullptr);
    luaL_addvalue(&b);
  }
  luaL_pushresult(&b);
  std::size_t length = 0;
  const char* text = lua_tolstring(L, -1, &length);
  print_line(L, text, length);
  return 0;
}

// math.random on the program's generator (seed 001 §3.2: "random values, random seeds, controled
// seeds"), same argument rules as Lua's.
int safe_random(lua_State* L) {
  shape::Rng& rng = program(L).rng;
  switch (lua_gettop(L)) {
    case 0:
      lua_pushnumber(L, rng.unit());
      return 1;
    case 1:
    case 2: {
      const lua_Integer lo = lua_gettop(L) == 1 ? 1 : luaL_checkinteger(L, 1);
      const lua_Integer hi = luaL_checkinteger(L, lua_gettop(L));
      luaL_argcheck(L, lo <= hi, lua_gettop(L), "interval is empty");
      lua_pushinteger(L, rng.integer(lo, hi));
      return 1;
    }
    default:
      return luaL_error(L, "wrong number of arguments");
  }
}

int safe_randomseed(lua_State* L) {
  const lua_Integer seed = luaL_checkinteger(L, 1);
  program(L).rng = shape::Rng(shape::mix64(static_cast<std::uint64_t>(seed)));
  return 0;
}

// Lua patterns backtrack in C, where the instruction hook never runs: a failing match costs up
// to n^k steps for a subject of n bytes and k repetition items (`*`, `+`, `-`). Calls whose bound
// exceeds kPatternBudget are refused before they run.
constexpr double kPatternBudget = 1e9;

int repetition_items(const char* pattern, std::size_t length) {
  int items = 0;
  bool in_set = false;
  for (std::size_t i = 0; i < length; ++i) {
    const char c = pattern[i];
    if (c == '%') {
      ++i;  // an escaped character or class
    } else if (in_set) {
      in_set = c != ']';
    } else if (c == '[') {
      in_set = true;
      if (i + 1 < length && pattern[i + 1] == '^') ++i;
      if (i + 1 < length && pattern[i + 1] == ']') ++i;
    } else if (c == '*' || c == '+' || c == '-') {
      ++items;
    }
  }
  return items;
}

int guarded_pattern(lua_State* L) {
  std::size_t subject = 0;
  std::size_t length = 0;
  if (lua_type(L, 1) == LUA_TSTRING && lua_type(L, 2) == LUA_TSTRING) {
    lua_tolstring(L, 1, &subject);
    const char* pattern = lua_tolstring(L, 2, &length);
    const int items = repetition_items(pattern, length);
    if (items > 1 && std::pow(static_cast<double>(subject), items) > kPatternBudget) {
      return luaL_error(L,
                        "pattern with %d repetition items is too costly on a %d-byte string "
                        "(split the text or simplify the pattern)",
                        items, static_cast<int>(subject));
    }
  }
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

void open_libraries(lua_State* L) {
  static constexpr luaL_Reg kLibraries[] = {{LUA_GNAME, luaopen_base},
                                            {LUA_STRLIBNAME, luaopen_string},
                                            {LUA_TABLIBNAME, luaopen_table},
                                            {LUA_MATHLIBNAME, luaopen_math},
                                            {LUA_UTF8LIBNAME, luaopen_utf8}};
  for (const luaL_Reg& lib : kLibraries) {
    luaL_requiref(L, lib.name, lib.func, 1);
    lua_pop(L, 1);
  }
  lua_pushglobaltable(L);
  // The original load, kept as an upvalue of safe_load only.
  lua_newtable(L);
  lua_getfield(L, -2, "load");
  lua_setfield(L, -2, "load");
  lua_pushcclosure(L, safe_load, 1);
  lua_setfield(L, -2, "load");
  for (const char* name : {"dofile", "loadfile", "warn"}) {
    lua_pushnil(L);
    lua_setfield(L, -2, name);
  }
  lua_pushcfunction(L, safe_pcall);
  lua_setfield(L, -2, "pcall");
  lua_pushcfunction(L, safe_xpcall);
  lua_setfield(L, -2, "xpcall");
  lua_pushcfunction(L, safe_collectgarbage);
  lua_setfield(L, -2, "collectgarbage");
  lua_pushcfunction(L, safe_print);
  lua_setfield(L, -2, "print");
  lua_getfield(L, -1, LUA_STRLIBNAME);
  lua_pushnil(L);
  lua_setfield(L, -2, "dump");
  for (const char* name : {"find", "match", "gmatch", "gsub"}) {
    lua_getfield(L, -1, name);
    lua_pushcclosure(L, guarded_pattern, 1);
    lua_setfield(L, -2, name);
  }
  lua_pop(L, 1);
  lua_getfield(L, -1, LUA_MATHLIBNAME);
  lua_pushcfunction(L, safe_random);
  lua_setfield(L, -2, "random");
  lua_pushcfunction(L, safe_randomseed);
  lua_setfield(L, -2, "randomseed");
  lua_pop(L, 2);
}

// ---- diagnostics

// Column of the operation's name on the line (the call), else of its first non-blank character.
std::uint32_t column_of(const base::Source& source, std::uint32_t line, std::string_view name) {
  const std::string_view text = source.line(line);
  if (!name.empty()) {
    for (std::size_t at = text.find(name); at != std::string_view::npos;
         at = text.find(name, at + 1)) {
      const bool starts = at == 0 || (std::isalnum(static_cast<unsigned char>(text[at - 1])) == 0 &&
                                      text[at - 1] != '_');
      const std::size_t end = at + name.size();
      const bool ends =
          end >= text.size() ||
          (std::isalnum(static_cast<unsigned char>(text[end])) == 0 && text[end] != '_');
      if (starts && ends) return static_cast<std::uint32_t>(at + 1);
    }
  }
  const std::size_t first = text.find_first_not_of(" \t");
  return first == std::string_view::npos ? 1 : static_cast<std::uint32_t>(first + 1);
}

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

// The Source line (lines end at '\n') where Lua's line `lua_line` starts. Lua also ends a line at
// a lone '\r' and counts "\r\n" and "\n\r" as one break (llex.c, inclinenumber), so a file with
// bare carriage returns has more Lua lines than Source lines.
std::uint32_t source_line(std::string_view text, std::uint32_t lua_line) {
  std::uint32_t line = 1, source = 1;
  for (std::size_t i = 0; i < text.size() && line < lua_line; ++i) {
    const char c = text[i];
    if (c != '\n' && c != '\r') continue;
    if (c == '\n') ++source;
    if (i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r') && text[i + 1] != c) {
      ++i;
      if (text[i] == '\n') ++source;
    }
    ++line;
  }
  return source;
}

// A Lua error message "<short_src>:<line>: <text>" (or any other text) as a diagnostic.
base::Diagnostic to_diagnostic(const base::Source& source, const std::string& short_src,
                               std::string message, int fallback_line, bool stopped) {
  int line = fallback_line;
  const std::string prefix = short_src + ":";
  if (starts_with(message, prefix)) {
    std::size_t i = prefix.size();
    int parsed = 0;
    while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i])) != 0) {
      parsed = parsed * 10 + (message[i] - '0');
      ++i;
    }
    if (i > prefix.size() && starts_with(std::string_view(message).substr(i), ": ")) {
      line = parsed;
      message.erase(0, i + 2);
    }
  }
  std::string code = "LUA002";
  std::string_view op;
  if (stopped) {
    code = starts_with(message, "instruction")  ? "LUA101"
           : starts_with(message, "memory")     ? "LUA102"
           : starts_with(message, "call depth") ? "LUA103"
                                                : "LUA104";
  } else if (starts_with(message, "in ")) {
    code = "LUA003";
  } else if (message.find("stack overflow") != std::string::npos) {
    code = "LUA103";
  }
  if (starts_with(message, "in ")) {
    const std::size_t colon = message.find(':');
    if (colon != std::string::npos) op = std::string_view(message).substr(3, colon - 3);
  }
  const std::uint32_t at =
      line > 0 ? source_line(source.text(), static_cast<std::uint32_t>(line)) : 0;
  base::Span span = at > 0 ? base::Span::at(source.name(), at, column_of(source, at, op))
                           : base::Span::whole(source.name());
  return base::Diagnostic::error(code, std::move(message), std::move(span));
}

// Message handler of the main call: keeps the message and notes the program's line, which is
// the location when the message has none of its own (e.g. error({}) or an error inside load()).
int message_handler(lua_State* L) {
  Runtime::Guard& g = guard(L);
  if (lua_type(L, 1) != LUA_TSTRING) {
    const char* type = luaL_typename(L, 1);
    lua_pushfstring(L, "error object is a %s value", type);
  } else {
    lua_pushvalue(L, 1);
  }
  const int line = lua_line(L, 1, &g.source);
  lua_pushinteger(L, line);
  lua_setfield(L, LUA_REGISTRYINDEX, "insula.error_line");
  return 1;
}

std::string chunk_name(const std::string& file) {
  return "=" + file;
}

// What Lua prints for chunk name "=file": the name cut to LUA_IDSIZE - 1 bytes (lobject.c).
std::string short_source(const std::string& file) {
  return file.substr(0, LUA_IDSIZE - 1);
}

}  // namespace

Runtime::Runtime(RunOptions options)
    : guard_(std::make_unique<Guard>()),
      program_(std::make_unique<Program>(options.seed)),
      options_(std::move(options)) {
  guard_->limits = options_.limits;
  guard_->program = program_.get();
  program_->assets = options_.assets;
  program_->max_components = options_.limits.components;
  program_->print = options_.print;
  guard_slot(*program_) = guard_.get();
  L_ = lua_newstate(allocate, guard_.get());
  if (L_ == nullptr) return;
  *static_cast<Program**>(lua_getextraspace(L_)) = program_.get();
  open_libraries(L_);
  // Parameters (--set) as the global table `params`.
  lua_newtable(L_);
  for (const auto& [name, value] : options_.params) {
    push_value(L_, value);
    lua_setfield(L_, -2, name.c_str());
  }
  lua_setglobal(L_, "params");
  open_bindings(L_);
  if (options_.lot) {
    const shape::RootResult root = program_->tree.create_root(*options_.lot);
    if (root.ok()) {
      push_component(L_, root.id);
      lua_setglobal(L_, "lot");
    }
  }
  guard_->L = L_;
}

Runtime::~Runtime() {
  if (L_ != nullptr) lua_close(L_);
}

std::vector<base::Diagnostic> Runtime::check(const base::Source& source) {
  lua_State* L = luaL_newstate();
  std::vector<base::Diagnostic> out;
  const int status = luaL_loadbufferx(L, source.text().data(), source.text().size(),
                                      chunk_name(source.name()).c_str(), "t");
  if (status != LUA_OK) {
    std::string message = lua_tostring(L, -1) != nullptr ? lua_tostring(L, -1) : "syntax error";
    base::Diagnostic d =
        to_diagnostic(source, short_source(source.name()), std::move(message), 0, false);
    d.code = "LUA001";
    out.push_back(std::move(d));
  }
  lua_close(L);
  return out;
}

std::vector<base::Diagnostic> Runtime::run(const base::Source& source) {
  std::vector<base::Diagnostic> out = check(source);
  if (!out.empty()) return out;
  if (L_ == nullptr) {
    out.push_back(base::Diagnostic::error("LUA102", "cannot create the Lua state (memory limit)",
                                          base::Span::whole(source.name())));
    return out;
  }
  program_->file = source.name();
  guard_->source = chunk_name(source.name());
  lua_pushcfunction(L_, message_handler);
  const int status =
      luaL_loadbufferx(L_, source.text().data(), source.text().size(), guard_->source.c_str(), "t");
  if (status != LUA_OK) {  // only a memory error can get here: check() compiled it
    out.push_back(base::Diagnostic::error("LUA102", "not enough memory to compile the program",
                                          base::Span::whole(source.name())));
    return out;
  }
  guard_->short_src = short_source(source.name());
  guard_->depth = 0;
  lua_sethook(L_, hook, LUA_MASKCOUNT | LUA_MASKCALL | LUA_MASKRET, kHookInterval);
  const int result = lua_pcall(L_, 0, 0, -2);
  lua_sethook(L_, nullptr, 0, 0);
  if (result == LUA_OK) {
    lua_pop(L_, 1);
    return out;
  }
  std::string message;
  if (result == LUA_ERRMEM && !program_->stopped) {
    program_->stopped = true;
    program_->stop_message = guard_->short_src + ":" + std::to_string(guard_->memory_line) + ": " +
                             limit_text("memory", guard_->limits.memory_bytes >> 20, " MB");
  }
  if (program_->stopped) {
    message = program_->stop_message;
  } else if (const char* text = lua_tostring(L_, -1); text != nullptr) {
    message = text;
  } else {
    message = "error object is not a string";
  }
  lua_getfield(L_, LUA_REGISTRYINDEX, "insula.error_line");
  const int line = static_cast<int>(lua_tointeger(L_, -1));
  lua_pop(L_, 3);
  out.push_back(
      to_diagnostic(source, guard_->short_src, std::move(message), line, program_->stopped));
  return out;
}

RunStats Runtime::stats() const {
  RunStats s;
  // The instructions since the last hook call are fewer than an interval: round up.
  s.instructions = (guard_->count_events + 1) * kHookInterval;
  s.peak_memory = guard_->peak;
  s.operations = program_->operations;
  return s;
}

shape::Scene collect_program(const Program& program) {
  // Repeated decorations share one mesh (seed 001 §4.5: "can therefore take advantage of
  // instancing"): glTF writes them as one mesh and a node per placement; the other writers expand
  // them (shape/part_mesh.h).
  shape::CollectOptions options;
  options.instances = true;
  shape::Scene scene = shape::collect(program.tree, options);
  // Components moved by connect() (seed 001 §3.4.2) live on as their placed copies only.
  for (shape::Building& b : scene.buildings) {
    std::erase_if(b.parts, [](const shape::Part& part) {
      return part.attributes.find(kConnectedAttribute) != part.attributes.end();
    });
  }
  std::erase_if(scene.buildings, [](const shape::Building& b) { return b.parts.empty(); });
  return scene;
}

}  // namespace insula::lua
