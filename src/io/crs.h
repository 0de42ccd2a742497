// Coordinate reference systems for footprint input: what a CRS is (geographic degrees or projected
// meters), the UTM zone of a place, and reprojection of points. PROJ (Debian libproj-dev) does
// the work; its headers stay inside crs.cc. Which CRS a GeoJSON file is read in and built in is
// decided by the reader (docs/geojson.md, "Coordinates, units and CRS").
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "kernel/vec.h"

namespace insula::io {

struct CrsInfo {
  std::string name;         // as asked for, upper-cased: "EPSG:32633", "OGC:CRS84"; Web
                            // Mercator's unofficial codes (EPSG:900913, 102100...) become EPSG:3857
  std::string title;        // PROJ's name: "WGS 84 / UTM zone 33N"
  bool geographic = false;  // axes are longitude and latitude in degrees
  std::string unit;         // the horizontal axis unit: "degree", "metre", "US survey foot"
  bool mercator = false;    // a normal-aspect Mercator (Web Mercator): meters x 1 / cos(latitude)
  bool metric = false;      // projected, in ground meters: footprints can be built in it
};

// What PROJ's database knows of `name` ("EPSG:N", "urn:ogc:def:crs:EPSG::N", "OGC:CRS84"...);
// nullopt with `error` set when PROJ does not know it or it is not a 2D horizontal CRS.
std::optional<CrsInfo> describe_crs(const std::string& name, std::string& error);

// Empty when footprints can be built in `name` (a projected CRS in ground meters: not Web
// Mercator), else why not
// ("EPSG:4326 (WGS 84) is geographic (degrees); name a projected CRS in meters").
std::string buildable_crs(const std::string& name);

// "EPSG:326NN" (north) or "EPSG:327NN" (south): the WGS 84 / UTM zone of (lon, lat) in degrees,
// by the regular 6-degree grid (the Norway and Svalbard exceptions are not applied).
std::string utm_crs(double lon, double lat);

// Reprojects `points` in place from CRS `from` to CRS `to`. x is always east (longitude) and y
// north (latitude), whatever axis order the CRS's definition gives. A point that cannot be
// transformed becomes non-finite. Returns an empty string, or why no transformation exists.
std::string reproject(const std::string& from, const std::string& to,
                      std::vector<kernel::Vec2>& points);

// Earth-centred, Earth-fixed coordinates (EPSG:4978, meters) of `points` given in `crs` with z as
// the height above the ellipsoid, in place. Returns an empty string, or why no transformation
// exists; a point PROJ cannot transform becomes non-finite.
std::string to_ecef(const std::string& crs, std::vector<kernel::Vec3>& points);

// For each point of `at` (a point of `crs` with its ellipsoidal height), the affine map, a
// column-major 4x4 matrix as 3D Tiles' `transform` wants it, that takes local coordinates around
// it (x along the CRS's east axis, y along its north axis, z up, meters) to ECEF. Its columns are
// the images of unit steps from the point, so the map includes the projection's grid convergence
// and scale factor there. One PROJ set-up for all points. Empty with `error` set when PROJ cannot
// transform one of them.
std::vector<std::array<double, 16>> ecef_frames(const std::string& crs,
                                                const std::vector<kernel::Vec3>& at,
                                                std::string& error);

}  // namespace insula::io
