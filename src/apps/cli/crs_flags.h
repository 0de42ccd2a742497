// The footprint reading flags as given: --crs, --out-crs and --id-attr (geojson_options.h turns
// them into reader options).
#pragma once

#include <string>

namespace insula::cli {

struct CrsFlags {
  std::string crs;      // --crs EPSG:N: the input's CRS when the file names none
  std::string out_crs;  // --out-crs EPSG:N: the CRS to build in and write
  std::string id_attr;  // --id-attr NAME: the property that names each building
};

}  // namespace insula::cli
