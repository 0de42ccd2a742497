// The CGA derivation engine (seed 004 §II "Procedural building of models"; Müller et al. 2006).
// A lot's start shapes are derived to terminal shapes: rules of priority level 1 before level 2
// and so on, the first rule (file order) of a level whose condition holds is applied, among its
// alternatives one is chosen by probability from the shape's own seeded generator, a shape that
// no rule applies to is terminal, and ε removes a shape. Each lot is derived on its own (so lots
// run in parallel and the result depends only on the seed and the lot index).
//
// State is compact (docs/cga-derivation.md, "Memory"): a pending shape is a 152-byte record
// (scope, seed, symbol, geometry handle, attribute-chain handle, depth) and a terminal a 136-byte
// record; boxes and rectangles are represented by their scope plus interned face tags, and split /
// repeat on them are pure scope math through the shape layer's own cores (shape/ops_fast.h), so
// they give exactly shape::split's scopes and geometry. Every other operation runs the shape
// layer's operation (shape::registry()) on a one-shape tree. Meshes are built only by to_scene().
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/polygon.h"
#include "lang/cga/compile.h"
#include "shape/operation.h"
#include "shape/scene.h"
#include "shape/scope.h"
#include "shape/value.h"

namespace insula::lang::cga {

struct DeriveLimits {
  // Rule applications along one path from a start shape (runaway recursion); at most 65535.
  std::uint32_t max_depth = 10000;
  // Shapes created per lot (runaway growth).
  std::uint64_t max_shapes = 10000000;
};

// CityEngine's file and asset functions (fileExists, fileSearch, fileRandom, assetInfo,
// imageInfo, readStringTable, readFloatTable), answered by the app: the front-end reads no files.
// Thread-safe (lots derive in parallel). Without one, those functions are an evaluation error.
class FileQueries {
 public:
  virtual ~FileQueries() = default;
  virtual bool exists(const std::string& path) const = 0;
  // A `;`-ended list of the matching files ("" when none); sets `error` on a bad query.
  virtual std::string search(const std::string& query, std::string& error) const = 0;
  // The entry at floor(random * count) of search(query).
  virtual std::string random(const std::string& query, double random, std::string& error) const = 0;
  virtual std::optional<double> asset_info(const std::string& path, const std::string& what,
                                           std::string& error) const = 0;
  virtual std::optional<double> image_info(const std::string& path, const std::string& what,
                                           std::string& error) const = 0;
  // The text of a file (readStringTable, readFloatTable); nullopt with `error` when unreadable.
  virtual std::optional<std::string> read_text(const std::string& path,
                                               std::string& error) const = 0;
};

// Where the lots' local meters lie on the Earth (CityEngine's getGeoCoord): `origin` is the local
// origin in the scene CRS's units, lon_lat() takes scene CRS coordinates to WGS 84 degrees
// (nullopt without a CRS or a transformation).
struct GeoReference {
  virtual ~GeoReference() = default;
  kernel::Vec3 origin;
  virtual std::optional<kernel::Vec2> lon_lat(kernel::Vec2 crs_xy) const = 0;
};

struct DeriveOptions {
  std::uint64_t seed = 0;
  DeriveLimits limits;
  // --set name=value overrides (win over lot properties, which win over attr defaults).
  std::vector<std::pair<std::string, shape::Value>> sets;
  // Keep terminal records for to_scene (false: count only, e.g. a --report-only run).
  bool keep_terminals = true;
  // Assets for I(), Pshape() and i(); "cube" is built in. May be null (only "cube" resolves).
  const shape::AssetProvider* assets = nullptr;
  const FileQueries* files = nullptr;
  const GeoReference* geo = nullptr;  // null: getGeoCoord's x and y are the local meters
  // i() results alike in every vertex and face share one mesh, so to_scene(..., true) can place
  // them as instances of it (GLB with EXT_mesh_gpu_instancing, issue 21).
  bool share_inserts = false;
};

// A lot: one or more footprint polygons (a GeoJSON Polygon or MultiPolygon, local meters) and the
// feature's properties (they override attr defaults of the same name).
struct Lot {
  std::string id;
  std::vector<kernel::Polygon> polygons;
  shape::AttributeMap properties;
  // Optional, per polygon: the first edge as written in the input (GeoJSON order). Readers
  // normalise rings to counter-clockwise, which moves a clockwise ring's first edge; when given,
  // the outer ring is rotated so the edge with these end points (either direction) comes first,
  // and the start shape's x axis runs along it. Empty: the ring's own first edge.
  std::vector<std::array<kernel::Vec2, 2>> first_edges;
  // Its feature's position in the input file, the number its seed mixes in (derive_lot's
  // lot_index): a feature skipped before it (invalid, under --keep-going) does not change it, so
  // mending that feature leaves the other buildings as they were.
  std::size_t number = 0;
};

// Geometry of a pending or terminal shape, by handle into LotResult::geometry.
struct Geometry {
  enum class Kind : std::uint8_t { kNone, kBox, kRect, kMesh } kind = Kind::kNone;
  std::array<kernel::FaceTag, 6> tags{};  // kBox (and kMesh that is a box: box_like)
  kernel::FaceTag tag;                    // kRect (and kMesh that is a rectangle: rect_like)
  bool box_like = false;
  bool rect_like = false;
  double area = 0;                                 // kMesh flat: outline area
  std::shared_ptr<const kernel::Mesh> mesh;        // kMesh
  std::shared_ptr<const kernel::Polygon> outline;  // kMesh flat

  bool flat() const { return kind == Kind::kRect || (kind == Kind::kMesh && outline); }
};

struct Terminal {
  shape::Scope scope;
  SymbolId symbol = kNoSymbol;
  std::uint32_t geometry = 0;
  std::uint32_t attrs = 0;  // attribute chain node (0: none)
};

// A value set by set() or color() on a shape, seen by its descendants: a persistent linked list.
struct AttrNode {
  std::uint32_t parent = 0;
  std::uint32_t attr = 0;
  Value value;
};

struct ReportEntry {
  double sum = 0;
  std::uint64_t count = 0;
};

// Terminal records in blocks that never move once filled (no doubling copies). Blocks grow from
// 32 records to 4096 (a lot with a handful of terminals does not pay for a big block). A block is
// raw storage, each record written once by push (default-constructing a block first wrote every
// record twice, and the first writes, to memory not yet in cache, cost more than the records).
class TerminalStore {
 public:
  void push(const Terminal& t);
  std::size_t size() const { return size_; }
  const Terminal& operator[](std::size_t i) const;
  std::size_t capacity_bytes() const { return capacity_ * sizeof(Terminal); }

 private:
  static_assert(std::is_trivially_copyable_v<Terminal> &&
                std::is_trivially_destructible_v<Terminal>);
  struct Release {
    void operator()(Terminal* block) const { ::operator delete(block); }
  };
  std::vector<std::unique_ptr<Terminal, Release>> blocks_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

struct LotResult {
  bool ok = false;
  std::vector<base::Diagnostic> diagnostics;  // errors (ok == false) and warnings
  std::uint64_t shapes = 0;                   // shapes created (start shapes included)
  std::uint64_t terminals = 0;                // leaf shapes (ε excluded)
  std::uint64_t rule_applications = 0;
  std::vector<std::uint64_t> symbol_counts;    // by SymbolId: shapes created with that symbol
  std::vector<std::string> prints;             // print() lines, in derivation order
  std::map<std::string, ReportEntry> reports;  // report() sums
  shape::AttributeMap attributes;  // the lot's resolved attr values + properties (arrays as text)
  std::size_t peak_pending = 0;    // largest number of pending shapes at once
  TerminalStore terminals_store;   // when keep_terminals
  // What terminal records refer to; empty when none are kept (DeriveOptions::keep_terminals).
  std::vector<Geometry> geometry;    // handle 0: no geometry
  std::vector<AttrNode> attr_nodes;  // node 0: the empty chain
};

// Derives lot number `lot_index` (seeds it as child_seed(mix64(options.seed), lot_index)). Never
// throws; errors (limits, evaluation errors) are diagnostics with ok == false.
LotResult derive_lot(const Program& program, const Lot& lot, std::size_t lot_index,
                     const DeriveOptions& options);

// Without --lot: one square lot of `lotWidth` x `lotDepth` meters when the grammar declares those
// attributes with constant defaults (--set applies), else 20 x 20 m.
Lot default_lot(const Program& program, const DeriveOptions& options);

// The export model: one Building per lot (id = lot id, attributes = the lot's), one Part per
// terminal with geometry (name = its symbol, attributes = its set()/color() values, faces coloured
// by color()). With `instances`, terminals of a lot that show one shared mesh (i() results with
// DeriveOptions::share_inserts) in one colour and without a uv map become instances of it
// (Part::instance_of, placed by the terminal's scope). With `merge_alike`, a lot's terminals
// with the same name, attributes and uv map are one part (in the order each first comes, faces
// in terminal order): a graph's rule node hands a facade to the graph as a dozen entities, not
// hundreds (docs/graph-executor.md); instances stay parts of their own.
shape::Scene to_scene(const Program& program, const std::vector<Lot>& lots,
                      const std::vector<LotResult>& results, bool instances = false,
                      bool merge_alike = false);
// The same, consuming `results`: each lot's records are freed once its building is made, so a
// run does not hold every lot's records and the whole scene at once (3,000 district lots to one
// GLB: peak 971 MB -> 791 MB, docs/PERFORMANCE.md).
shape::Scene to_scene(const Program& program, const std::vector<Lot>& lots,
                      std::vector<LotResult>&& results, bool instances = false,
                      bool merge_alike = false);

// The report of issue 4: shapes, terminals, symbols {name: count}, rule_applications, reports,
// lots (count). Sums over `results` in lot order.
struct Totals {
  std::uint64_t shapes = 0;
  std::uint64_t terminals = 0;
  std::uint64_t rule_applications = 0;
  std::map<std::string, std::uint64_t> symbols;
  std::map<std::string, ReportEntry> reports;
};
Totals totals(const Program& program, const std::vector<LotResult>& results);

// The "derivation" golden stage: counts, symbols, then one line per terminal (symbol, geometry
// kind, scope origin and size rounded to 1e-6 m), lot by lot.
std::string dump_derivation(const Program& program, const std::vector<LotResult>& results);

// The built-in assets ("cube": the unit box, walls around and roof/ground on top/bottom) in front
// of `next` (may be null).
class BuiltinAssets : public shape::AssetProvider {
 public:
  explicit BuiltinAssets(const shape::AssetProvider* next) : next_(next) {}
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override;

 private:
  const shape::AssetProvider* next_;
};

}  // namespace insula::lang::cga
