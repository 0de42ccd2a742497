#include "io/gltf_placement.h"

#include <cmath>

namespace insula::io::gltf {
namespace {

std::array<double, 3> y_up(kernel::Vec3 v) {
  return {v.x, v.z, -v.y};
}

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The unit quaternion of rotation matrix `r` (columns), Shepperd's method: the largest of the
// four candidates' squares is taken first, so the division stays well conditioned.
std::array<double, 4> quaternion(const std::array<std::array<double, 3>, 3>& r) {
  const auto m = [&r](int row, int col) { return r[col][row]; };
  const double trace = m(0, 0) + m(1, 1) + m(2, 2);
  std::array<double, 4> q{};
  if (trace > 0) {
    const double s = 2 * std::sqrt(1 + trace);
    q = {(m(2, 1) - m(1, 2)) / s, (m(0, 2) - m(2, 0)) / s, (m(1, 0) - m(0, 1)) / s, s / 4};
  } else if (m(0, 0) > m(1, 1) && m(0, 0) > m(2, 2)) {
    const double s = 2 * std::sqrt(1 + m(0, 0) - m(1, 1) - m(2, 2));
    q = {s / 4, (m(0, 1) + m(1, 0)) / s, (m(0, 2) + m(2, 0)) / s, (m(2, 1) - m(1, 2)) / s};
  } else if (m(1, 1) > m(2, 2)) {
    const double s = 2 * std::sqrt(1 + m(1, 1) - m(0, 0) - m(2, 2));
    q = {(m(0, 1) + m(1, 0)) / s, s / 4, (m(1, 2) + m(2, 1)) / s, (m(0, 2) - m(2, 0)) / s};
  } else {
    const double s = 2 * std::sqrt(1 + m(2, 2) - m(0, 0) - m(1, 1));
    q = {(m(0, 2) + m(2, 0)) / s, (m(1, 2) + m(2, 1)) / s, s / 4, (m(1, 0) - m(0, 1)) / s};
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q) c /= n;
  return q;
}

}  // namespace

Affine y_up(const kernel::Transform& t) {
  return Affine{{y_up(t.x), y_up(t.z), y_up(-t.y)}, y_up(t.t)};
}

Affine relative_to(const Affine& a, const std::array<double, 3>& offset, double scale) {
  Affine out = a;
  for (auto& column : out.columns) {
    for (double& c : column) c /= scale;
  }
  for (std::size_t k = 0; k < 3; ++k) out.translation[k] = (a.translation[k] - offset[k]) / scale;
  return out;
}

Affine dequantization(const std::array<double, 3>& offset, double scale) {
  return Affine{{{{scale, 0, 0}, {0, scale, 0}, {0, 0, scale}}}, offset};
}

Affine compose(const Affine& a, const Affine& b) {
  const auto apply = [&a](const std::array<double, 3>& v) {
    std::array<double, 3> out{};
    for (std::size_t r = 0; r < 3; ++r) {
      out[r] = a.columns[0][r] * v[0] + a.columns[1][r] * v[1] + a.columns[2][r] * v[2];
    }
    return out;
  };
  Affine out;
  for (std::size_t c = 0; c < 3; ++c) out.columns[c] = apply(b.columns[c]);
  out.translation = apply(b.translation);
  for (std::size_t r = 0; r < 3; ++r) out.translation[r] += a.translation[r];
  return out;
}

std::array<double, 16> matrix(const Affine& a) {
  std::array<double, 16> m{};
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t r = 0; r < 3; ++r) m[4 * c + r] = a.columns[c][r];
  }
  for (std::size_t r = 0; r < 3; ++r) m[12 + r] = a.translation[r];
  m[15] = 1;
  return m;
}

std::optional<Trs> decompose(const Affine& a) {
  Trs trs;
  trs.translation = a.translation;
  std::array<std::array<double, 3>, 3> r = a.columns;
  for (std::size_t k = 0; k < 3; ++k) {
    trs.scale[k] = std::sqrt(dot(r[k], r[k]));
    if (!(trs.scale[k] > 0) || !std::isfinite(trs.scale[k])) return std::nullopt;
    for (double& c : r[k]) c /= trs.scale[k];
  }
  constexpr double kTolerance = 1e-9;
  if (std::abs(dot(r[0], r[1])) > kTolerance || std::abs(dot(r[0], r[2])) > kTolerance ||
      std::abs(dot(r[1], r[2])) > kTolerance) {
    return std::nullopt;
  }
  // A mirror: the x scale takes the sign, the rest stays a rotation.
  if (dot(cross(r[0], r[1]), r[2]) < 0) {
    trs.scale[0] = -trs.scale[0];
    for (double& c : r[0]) c = -c;
  }
  trs.rotation = quaternion(r);
  return trs;
}

}  // namespace insula::io::gltf
