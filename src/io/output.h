// Chooses the writer for an output path by its extension (design.md, "Outputs").
#pragma once

#include <filesystem>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "io/cityjson_writer.h"
#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "io/png_renderer.h"
#include "io/svg_writer.h"
#include "io/tileset_writer.h"
#include "shape/scene.h"

namespace insula::io {

// .obj, .glb, .gltf, .city.json, .city.jsonl, .svg, .png (case-insensitive), and a file named
// tileset.json (3D Tiles: the tileset and its tiles/ folder beside it).
bool is_supported_output(const std::string& path);
// "obj", "glb", "gltf", "cityjson", "cityjsonseq", "3dtiles", "svg", "png"; empty when
// unsupported.
std::string output_format_name(const std::string& path);
// Options of the formats that have any (the others ignore them).
struct OutputOptions {
  RenderOptions render;
  SvgOptions svg;
  ObjOptions obj;
  GltfOptions gltf;
  TilesetOptions tiles;
  CityJsonOptions cityjson;
};

// Writes the scene in the path's format, atomically. Empty string on success, else the reason.
std::string write_scene(const shape::Scene& scene, const std::string& path,
                        const OutputOptions& options = {});
// The files a path's writer creates: the path itself, for OBJ its .mtl and origin sidecar, for
// 3D Tiles the tiles folder.
std::vector<std::string> files_of_output(const std::string& path);

// Writes several files as one transaction: a file that already exists is first moved aside (to
// PATH.insula-backup), and roll_back() removes everything the transaction wrote and puts the moved
// files back, so a failed or interrupted run neither leaves partial output nor loses the user's
// earlier files; commit() drops the backups. Every step asks `cancelled` first (an interruption,
// apps/cli/interrupt.h) and fails when it answers true; commit() asks last, so a run cancelled at
// any moment before the commit point keeps the old files. The writes may come from several threads.
// Destroying an uncommitted transaction rolls it back.
class OutputTransaction {
 public:
  explicit OutputTransaction(std::function<bool()> cancelled = {});
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // The scene in the path's format (with an OBJ's .mtl). Empty string on success, else the reason.
  std::string write_scene(const shape::Scene& scene, const std::string& path,
                          const OutputOptions& options = {});
  // Makes the files of an output free for a writer that writes them itself (a tileset written
  // tile by tile): a 3D Tiles folder is made when missing. Empty string on success, else the
  // reason.
  std::string claim_output(const std::string& path);
  // A text file (a report, a grammar). Empty string on success, else the reason.
  std::string write_text(const std::string& path, std::string_view content);
  // Keeps what was written. Empty string on success; when cancelled, rolls back and says so.
  std::string commit();
  void roll_back();

 private:
  std::string claim(const std::vector<std::string>& files);
  std::string make_folder(const std::filesystem::path& folder);
  std::string cancelled_error() const;

  std::function<bool()> cancelled_;
  std::mutex mutex_;                // the lists below
  std::vector<std::string> moved_;  // the user's files, moved aside
  std::set<std::string> created_;   // what this transaction writes (paths now free for it)
  bool finished_ = false;
};
// Checks before any work that every output's directory exists; empty string when it does.
std::string check_output_directories(const std::vector<std::string>& paths);

}  // namespace insula::io
