// libFuzzer target for the OBJ asset reader (io/obj_reader.h, docs/formats.md "OBJ reader"):
// assets come from users' folders through componentFromFile and CGA's i(). Beyond "no crash, no
// hang, no sanitizer report" it checks the reader's contract on every input:
//  - a failure carries at least one error, a success none; every diagnostic has an OBJ code, a
//    message and a line inside the file (or names the whole file);
//  - a mesh read has at least one face, every face at least 3 vertices, every index in range and
//    every position finite; a face's material index names one of the materials read.
//
// Builds as fuzz/geojson_fuzz.cc: libFuzzer with clang and INSULA_FUZZ=ON, a replay main with
// INSULA_FUZZ_REPLAY; tests/io/obj_replay_test.cc includes it with INSULA_FUZZ_NO_ENTRY.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "base/diagnostic.h"
#include "io/obj_reader.h"

namespace insula::fuzz {

// Empty when parse_obj kept its contract on `text`, else what broke.
inline std::string check_obj(std::string_view text) {
  std::size_t lines = 1;
  for (const char c : text) lines += c == '\n' ? 1 : 0;
  const base::Result<io::ObjModel> result = io::parse_obj(text, "fuzz.obj");
  for (const base::Diagnostic& d : result.diagnostics()) {
    if (d.message.empty() || d.code.rfind("OBJ", 0) != 0) return "bad code or empty message";
    // Line 0: the whole file ("the file has no faces").
    if (d.span.line > lines + 1) return "diagnostic outside the file";
    if (base::render(d).empty()) return "empty rendering";
  }
  const bool errors = base::has_errors(result.diagnostics());
  if (!result.ok()) return errors ? std::string() : "failure without an error diagnostic";
  if (errors) return "success with an error diagnostic";
  const kernel::Mesh& mesh = result.value().mesh;
  if (mesh.face_count() == 0) return "a model without faces";
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const kernel::Vec3 p = mesh.position(static_cast<std::uint32_t>(v));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return "position";
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto loop = mesh.face(f);
    if (loop.size() < 3) return "a face with fewer than 3 vertices";
    for (const std::uint32_t v : loop) {
      if (v >= mesh.vertex_count()) return "face index out of range";
    }
    if (mesh.tag(f).material > result.value().materials.size()) return "material out of range";
  }
  return {};
}

}  // namespace insula::fuzz

#ifndef INSULA_FUZZ_NO_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      insula::fuzz::check_obj(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "obj_fuzz: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
#endif

#ifdef INSULA_FUZZ_REPLAY
#define INSULA_FUZZ_REPLAY_NAME "obj_fuzz_replay"
#include "replay_main.h"
#endif
