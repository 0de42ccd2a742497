#include "kernel/opening_frame.h"

#include <algorithm>
#include <array>
#include <span>

#include "kernel/solids.h"

namespace insula::kernel {

void add_opening_frame(Mesh& mesh, const WallFrame& frame, double thickness, const Opening& o,
                       FrameKind kind, const FrameProfile& profile, const FrameTags& tags) {
  const double fw = profile.width;
  const double fd = profile.depth;
  if (!(fw > 0) || !(fd > 0) || !(thickness > 0) || !(o.width > 0) || !(o.height > 0)) return;
  const bool door = kind == FrameKind::kDoor;
  const double bottom = door ? o.sill : o.sill - fw;
  const double top = o.sill + o.height;
  // At most eight frame boxes and the pane: one append grows the mesh once (a storey has
  // hundreds of openings).
  std::array<BoxEdges, 9> boxes;
  std::size_t count = 0;
  const auto box = [&](double u0, double u1, double v0, double v1, double w0, double w1) {
    boxes[count++] = {frame.map(u0, v0, w0), frame.u_axis * (u1 - u0), frame.v_axis * (v1 - v0),
                      frame.normal * (w1 - w0)};
  };
  for (const auto& [w0, w1] : {std::pair{thickness, thickness + fd}, std::pair{-fd, 0.0}}) {
    box(o.u - fw, o.u, bottom, top + fw, w0, w1);
    box(o.u + o.width, o.u + o.width + fw, bottom, top + fw, w0, w1);
    box(o.u, o.u + o.width, top, top + fw, w0, w1);
    if (!door) box(o.u, o.u + o.width, o.sill - fw, o.sill, w0, w1);
  }
  const double inner = std::min(door ? profile.leaf : profile.pane, thickness / 4);
  const bool pane = inner > 0;
  if (pane) {
    boxes[count++] = {frame.map(o.u, o.sill, thickness / 2 - inner / 2), frame.u_axis * o.width,
                      frame.v_axis * o.height, frame.normal * inner};
  }
  add_boxes(mesh, std::span<const BoxEdges>(boxes.data(), count), tags.frame);
  if (pane) {
    for (std::size_t f = mesh.face_count() - 6; f < mesh.face_count(); ++f) mesh.tag(f) = tags.pane;
  }
}

}  // namespace insula::kernel
