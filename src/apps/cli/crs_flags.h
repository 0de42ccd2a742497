// --crs and --out-crs as given (geojson_options.h turns them into reader options).
#pragma once

#include <string>

namespace insula::cli {

struct CrsFlags {
  std::string crs;      // --crs EPSG:N: the input's CRS when the file names none
  std::string out_crs;  // --out-crs EPSG:N: the CRS to build in and write
};

}  // namespace insula::cli
