// Small value types for 2D and 3D points and directions, in meters. World space is right-handed
// with Z up (design.md, "Coordinates and units").
#pragma once

#include <cmath>

namespace insula::kernel {

struct Vec2 {
  double x = 0;
  double y = 0;

  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
  friend Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
  friend Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
  Vec2& operator+=(Vec2 b) { return *this = *this + b; }
  Vec2& operator-=(Vec2 b) { return *this = *this - b; }
  friend bool operator==(Vec2 a, Vec2 b) = default;
};

struct Vec3 {
  double x = 0;
  double y = 0;
  double z = 0;

  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
  friend Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3 operator*(double s, Vec3 a) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
  Vec3& operator+=(Vec3 b) { return *this = *this + b; }
  Vec3& operator-=(Vec3 b) { return *this = *this - b; }
  friend bool operator==(Vec3 a, Vec3 b) = default;
};

inline double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
// z of the 3D cross product: > 0 when b is counter-clockwise of a.
inline double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
inline double length(Vec2 a) {
  return std::hypot(a.x, a.y);
}
inline Vec2 normalized(Vec2 a) {
  const double l = length(a);
  return l > 0 ? a / l : Vec2{};
}
// Rotated a quarter turn counter-clockwise.
inline Vec2 perp(Vec2 a) {
  return {-a.y, a.x};
}

inline double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) {
  return std::sqrt(dot(a, a));
}
inline Vec3 normalized(Vec3 a) {
  const double l = length(a);
  return l > 0 ? a / l : Vec3{};
}

inline Vec3 lift(Vec2 p, double z) {
  return {p.x, p.y, z};
}
inline Vec2 drop(Vec3 p) {
  return {p.x, p.y};
}

}  // namespace insula::kernel
