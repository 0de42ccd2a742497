// The identity of every part of a glTF scene written by building (EXT_structural_metadata, with
// EXT_mesh_features ids on the vertices): one property table "parts", a row per part in scene
// order (building by building), whose row number is the part's feature id. Columns: `name` (the
// part's name: terminal symbol, room, component, storey), `kind` (BuildingPart, Storey, Room,
// Installation, Other), then one per attribute name any part carries, its own or (where it has
// none of its own) one it inherits (`shape::Part::inherited`, a 3D Tiles tile's building
// attributes): numbers every part has become FLOAT64, booleans every part has BOOLEAN, anything
// else text (numbers printed as in the JSON). The building is the node the part's mesh hangs
// from, so it is not repeated per row. Text columns are dictionary-coded where that is smaller:
// an ENUM of their distinct values (UINT8 or UINT16 codes; "(none)" or a longer variant is the
// noData value where a part lacks the attribute); a city has few distinct symbol names and
// colours but hundreds of thousands of parts. Columns of mostly distinct values (OpenStreetMap
// ids) stay STRING. Property ids are the attribute names made identifiers
// ([A-Za-z_][A-Za-z0-9_]*, unique); the class property's `name` keeps the attribute's own name.
// This is the metadata 3D Tiles reads too.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "io/gltf_buffers.h"
#include "io/json_stream.h"
#include "shape/scene.h"

namespace insula::io::gltf {

inline constexpr std::string_view kMetadataExtension = "EXT_structural_metadata";
// The property that names a feature's building in the property table.
inline constexpr std::string_view kBuildingIdProperty = "building_id";

// Buildings merged into one mesh (a 3D Tiles tile, `--gltf-nodes scene`) keep their identity as
// features: every part points at what it takes from its building (its attributes and, over them,
// its id as `building_id`), shared by the building's parts rather than copied. The id has a name
// of its own: OpenStreetMap's `building` tag (`hospital`) is one of the attributes it sits beside.
std::shared_ptr<const shape::AttributeMap> building_feature_attributes(
    const shape::Building& building);
// `part` as such a feature (an own `building_id` attribute gives way to the building's id).
void make_feature(shape::Part& part, std::shared_ptr<const shape::AttributeMap> building);
inline constexpr std::string_view kFeaturesExtension = "EXT_mesh_features";
// Feature ids of GPU instances (EXT_mesh_gpu_instancing's _FEATURE_ID_n attributes) are named on
// the node by this extension; EXT_mesh_features names those of a primitive's vertices only.
inline constexpr std::string_view kInstanceFeaturesExtension = "EXT_instance_features";

// "BuildingPart", "Storey", "Room", "Installation", "Other".
std::string_view kind_name(shape::PartKind kind);

class PartTable {
 public:
  // `has_row`: for each part in scene order, whether it has a row (empty: every part has one). A
  // writer leaves out the parts it writes no triangle of, so no row is one no vertex points at.
  explicit PartTable(const shape::Scene& scene, const std::vector<bool>& has_row = {});

  std::size_t rows() const { return rows_; }
  // Appends the columns to views of their own.
  void write_data(Buffers& buffers);
  // The root's "EXT_structural_metadata" member (the key and the object).
  void write_json(JsonStream& json, const Buffers& buffers) const;

 private:
  enum class Type { kString, kNumber, kBoolean };
  static constexpr std::uint32_t kAbsent = ~0U;  // a text cell the part lacks
  struct Column {
    std::string id;    // the property id
    std::string name;  // the attribute's own name (empty for name and kind)
    Type type = Type::kString;
    bool optional = false;  // some part lacks it (text and number columns)
    // kString: each row's value as an index into `values` (its distinct texts in order of first
    // use) or kAbsent; a city repeats few texts over many rows.
    std::vector<std::uint32_t> codes{};
    std::vector<std::string> values{};
    // While filling: the codes of `values`, open addressing by text hash (kAbsent: free).
    std::vector<std::uint32_t> index_of{};
    std::vector<double> numbers{};  // kNumber; NaN where the part lacks it
    double no_data_number = 0;      // kNumber, optional: the value written where a part lacks it
    std::vector<bool> booleans{};   // kBoolean
    // Dictionary coding of a text column (empty: written as STRING): the enum names in order,
    // and each value's enum code.
    std::vector<std::string> dictionary{};
    std::vector<std::uint32_t> enum_code{};
    std::string no_data{};  // the enum name of "lacks it"
    std::uint32_t values_view = 0;
    std::uint32_t offsets_view = 0;  // STRING
  };
  void find_columns(const shape::Scene& scene, const std::vector<bool>& has_row);
  void add_row(const shape::Part& part, std::size_t index);
  std::size_t inherited_row(const shape::AttributeMap& map);
  static std::uint32_t intern(Column& column, std::string_view text);
  static std::uint32_t intern_value(Column& column, const shape::Value& value);
  static void grow_index(Column& column);
  static void make_dictionary(Column& column);
  void write_class_property(JsonStream& json, const Column& column) const;

  std::size_t rows_ = 0;
  std::vector<Column> columns_;
  std::vector<std::uint32_t> kind_codes_;  // by shape::PartKind: its code in "kind" (or kAbsent)
  // An inherited attribute map's value for each attribute column (nullptr: it has none), and the
  // text code of each, found once for the run of parts that share the map; flat, the last map's
  // entries from last_inherited_row_.
  std::vector<const shape::Value*> inherited_values_;
  std::vector<std::uint32_t> inherited_codes_;
  const shape::AttributeMap* last_inherited_ = nullptr;
  std::size_t last_inherited_row_ = 0;
};

}  // namespace insula::io::gltf
