// Hostile programs (docs/lua-api.md, "Sandbox" and "Limits"): each is stopped with its exact
// message, and a limit cannot be caught by pcall.
#include <gtest/gtest.h>

#include "run_util.h"

namespace insula::lua {
namespace {

using testing::run;

RunOptions small_limits() {
  RunOptions o;
  o.limits.instructions = 2'000'000;
  o.limits.memory_bytes = std::size_t{16} << 20;
  o.limits.call_depth = 100;
  o.limits.components = 1000;
  return o;
}

std::string error_of(const std::string& code) {
  return run(code, small_limits()).error();
}

TEST(LuaSandbox, InfiniteLoopHitsTheInstructionLimit) {
  EXPECT_EQ(error_of("local i = 0\nwhile true do i = i + 1 end"),
            "test.lua:2:1: error[LUA101]: instruction limit of 2000000 reached");
}

// Lua also breaks lines at a lone carriage return; the diagnostic names the line of the file as
// an editor shows it (found by lua_fuzz: Lua's line 53 of a one-line file, outside the program).
TEST(LuaSandbox, LinesBrokenByCarriageReturnsMapToTheFilesLines) {
  EXPECT_EQ(error_of("local a = 1\r\rlocal b = 2\r\n  error('boom')"),
            "test.lua:2:3: error[LUA002]: boom");
  EXPECT_EQ(error_of("local a = 1\n\rlocal b = 2\r\n\r  error('boom')"),
            "test.lua:3:1: error[LUA002]: boom");
  EXPECT_EQ(error_of("local\r\r\r\r\r\r\r\r = 1"),
            "test.lua:1:1: error[LUA001]: <name> expected near '='");
}

TEST(LuaSandbox, PcallCannotCatchALimit) {
  EXPECT_EQ(error_of("while true do\n  pcall(function() while true do end end)\nend"),
            "test.lua:2:3: error[LUA101]: instruction limit of 2000000 reached");
  EXPECT_EQ(
      error_of("local ok = xpcall(function() while true do end end, function(e) return e end)\n"
               "print(ok)"),
      "test.lua:1:1: error[LUA101]: instruction limit of 2000000 reached");
}

TEST(LuaSandbox, MemoryBomb) {
  EXPECT_EQ(error_of("local t = {}\nwhile true do t[#t + 1] = {1, 2, 3} end"),
            "test.lua:2:1: error[LUA102]: memory limit of 16 MB reached");
  EXPECT_EQ(error_of("local s = string.rep('x', 64 * 1024 * 1024)"),
            "test.lua:1:1: error[LUA102]: memory limit of 16 MB reached");
  EXPECT_EQ(error_of("local s = 'x'\nfor i = 1, 40 do s = s .. s end"),
            "test.lua:2:1: error[LUA102]: memory limit of 16 MB reached");
  EXPECT_EQ(error_of("print(pcall(string.rep, 'x', 1 << 26))"),
            "test.lua:1:1: error[LUA102]: memory limit of 16 MB reached");
}

TEST(LuaSandbox, DeepRecursion) {
  EXPECT_EQ(error_of("local function f(n)\n  return 1 + f(n + 1)\nend\nf(1)"),
            "test.lua:2:3: error[LUA103]: call depth limit of 100 reached");
  // Tail calls do not grow the stack and are allowed.
  const auto r =
      run("local function f(n) if n == 0 then return 0 end return f(n - 1) end\n"
          "print(f(100000))",
          small_limits());
  EXPECT_TRUE(r.ok()) << r.error();
}

TEST(LuaSandbox, NoOsIoRequireDebug) {
  EXPECT_EQ(error_of("os.execute('ls')"),
            "test.lua:1:1: error[LUA002]: attempt to index a nil value (global 'os')");
  EXPECT_EQ(error_of("local f = io.open('/etc/passwd')"),
            "test.lua:1:1: error[LUA002]: attempt to index a nil value (global 'io')");
  EXPECT_EQ(error_of("require('os')"),
            "test.lua:1:1: error[LUA002]: attempt to call a nil value (global 'require')");
  EXPECT_EQ(error_of("dofile('/etc/passwd')"),
            "test.lua:1:1: error[LUA002]: attempt to call a nil value (global 'dofile')");
  EXPECT_EQ(error_of("loadfile('/etc/passwd')"),
            "test.lua:1:1: error[LUA002]: attempt to call a nil value (global 'loadfile')");
  const auto r =
      run("print(os, io, package, debug, coroutine, require, string.dump, collectgarbage('count') "
          "> 0)");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, std::vector<std::string>{"nil\tnil\tnil\tnil\tnil\tnil\tnil\ttrue"});
  EXPECT_EQ(error_of("collectgarbage('stop')"),
            "test.lua:1:1: error[LUA002]: collectgarbage: option 'stop' is not allowed (collect, "
            "count, step)");
}

TEST(LuaSandbox, LoadIsTextOnly) {
  EXPECT_EQ(error_of("local f = load('\\27Lua...', 'x', 'b')"),
            "test.lua:1:1: error[LUA002]: load: binary chunks are not allowed (mode 't' only)");
  const auto r =
      run("local f, e = load('\\27Lua\\x54\\0'); print(f, e)\n"
          "print(load('return 1 + 2')())");
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r.printed.size(), 2U);
  EXPECT_EQ(r.printed[0], "nil\tattempt to load a binary chunk (mode is 't')");
  EXPECT_EQ(r.printed[1], "3");
}

TEST(LuaSandbox, PatternBombIsRefused) {
  EXPECT_EQ(
      error_of("local s = string.rep('a', 100000)\nprint(s:find(string.rep('a*', 8) .. 'b'))"),
      "test.lua:2:1: error[LUA002]: pattern with 8 repetition items is too costly on a "
      "100000-byte string (split the text or simplify the pattern)");
  const auto r = run("print(('key=value'):match('(%w+)=(%w+)'))");
  EXPECT_EQ(r.printed, std::vector<std::string>{"key\tvalue"});
}

TEST(LuaSandbox, ComponentLimit) {
  EXPECT_EQ(error_of("local c = component{size={1000, 1, 1}}\nrepeatSplit(c, 'x', 0.001)"),
            "test.lua:2:1: error[LUA003]: in repeat: would create 1000000 components (component "
            "limit 1000)");
  EXPECT_EQ(error_of("local c = component{size={10, 1, 1}}\n"
                     "for i = 1, 100 do pcall(split, query('leaf()'), 'x', '~1', '~1') end"),
            "test.lua:2:25: error[LUA104]: in split: component limit of 1000 reached");
}

TEST(LuaSandbox, ErrorsCarryTheirLine) {
  EXPECT_EQ(error_of("\n\nerror('boom')"), "test.lua:3:1: error[LUA002]: boom");
  EXPECT_EQ(error_of("local function f() error('deep', 2) end\n\nf()"),
            "test.lua:3:1: error[LUA002]: deep");
  EXPECT_EQ(error_of("error({})"), "test.lua:1:1: error[LUA002]: error object is a table value");
  EXPECT_EQ(error_of("  local x = nil\n  x.y = 1"),
            "test.lua:2:3: error[LUA002]: attempt to index a nil value (local 'x')");
  EXPECT_EQ(run("local x = = 1").error(),
            "test.lua:1:1: error[LUA001]: unexpected symbol near '='");
}

TEST(LuaSandbox, SeededRandomIsDeterministic) {
  RunOptions a;
  a.seed = 42;
  const std::string code = "print(math.random(1, 1000), math.random(1, 1000), math.random() < 1)";
  const auto r1 = run(code, a);
  const auto r2 = run(code, a);
  RunOptions b;
  b.seed = 43;
  const auto r3 = run(code, b);
  ASSERT_TRUE(r1.ok()) << r1.error();
  EXPECT_EQ(r1.printed, r2.printed);
  EXPECT_NE(r1.printed, r3.printed);
  EXPECT_EQ(run("math.random(5, 1)").error(),
            "test.lua:1:1: error[LUA002]: bad argument #2 to 'random' (interval is empty)");
}

TEST(LuaSandbox, ParamsFromSet) {
  RunOptions o;
  o.params = {{"floors", 3.0}, {"style", std::string("brick")}};
  const auto r = run("print(params.floors, params.style, params.missing)", o);
  EXPECT_EQ(r.printed, std::vector<std::string>{"3\tbrick\tnil"});
}

}  // namespace
}  // namespace insula::lua
