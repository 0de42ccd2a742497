#include "io/svg_reader.h"

#include <pugixml.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>

namespace insula::io {
namespace {

using kernel::Vec2;

// The affine map x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct Matrix {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  Matrix then(const Matrix& m) const {  // this, then m
    return {m.a * a + m.c * b, m.b * a + m.d * b,       m.a * c + m.c * d,
            m.b * c + m.d * d, m.a * e + m.c * f + m.e, m.b * e + m.d * f + m.f};
  }
};

constexpr int kCurveSegments = 8;
constexpr int kRoundSegments = 32;  // a circle or ellipse; an arc gets its share of them

// The points after `from` of the elliptic arc to `to` (SVG 1.1 appendix F.6.5: endpoint to centre
// parameterisation; radii scaled up when too small, a zero radius is a straight segment).
void elliptic_arc(Vec2 from, Vec2 to, const double (&arc)[5], std::vector<Vec2>& out) {
  double rx = std::abs(arc[0]);
  double ry = std::abs(arc[1]);
  const double phi = arc[2] * std::numbers::pi / 180;
  const bool large = arc[3] != 0;
  const bool sweep = arc[4] != 0;
  if (rx == 0 || ry == 0 || (from.x == to.x && from.y == to.y)) {
    out.push_back(to);
    return;
  }
  const double c = std::cos(phi);
  const double s = std::sin(phi);
  const double dx = (from.x - to.x) / 2;
  const double dy = (from.y - to.y) / 2;
  const double x1 = c * dx + s * dy;
  const double y1 = -s * dx + c * dy;
  const double lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
  if (lambda > 1) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
  const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
  double k = std::sqrt(std::max(0.0, num / den));
  if (large == sweep) k = -k;
  const double cx1 = k * rx * y1 / ry;
  const double cy1 = -k * ry * x1 / rx;
  const double cx = c * cx1 - s * cy1 + (from.x + to.x) / 2;
  const double cy = s * cx1 + c * cy1 + (from.y + to.y) / 2;
  const double t0 = std::atan2((y1 - cy1) / ry, (x1 - cx1) / rx);
  double dt = std::atan2((-y1 - cy1) / ry, (-x1 - cx1) / rx) - t0;
  if (sweep && dt < 0) dt += 2 * std::numbers::pi;
  if (!sweep && dt > 0) dt -= 2 * std::numbers::pi;
  const int n = std::max(
      1, static_cast<int>(std::ceil(std::abs(dt) / (2 * std::numbers::pi) * kRoundSegments)));
  for (int i = 1; i < n; ++i) {
    const double t = t0 + dt * i / n;
    out.push_back({cx + rx * std::cos(t) * c - ry * std::sin(t) * s,
                   cy + rx * std::cos(t) * s + ry * std::sin(t) * c});
  }
  out.push_back(to);
}

class Reader {
 public:
  Reader(std::string_view text, std::string name) : source_(std::move(name), std::string(text)) {}

  base::Result<std::vector<SvgOutline>> run() {
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed =
        doc.load_buffer(source_.text().data(), source_.text().size(), pugi::parse_default);
    if (!parsed) {
      error("SVG001", std::string("not well-formed XML: ") + parsed.description(),
            static_cast<std::size_t>(std::max<std::ptrdiff_t>(parsed.offset, 0)));
      return fail();
    }
    const pugi::xml_node root = doc.document_element();
    if (std::string_view(root.name()) != "svg") {
      error("SVG002", "the root element is <" + std::string(root.name()) + ">, not <svg>",
            static_cast<std::size_t>(root.offset_debug()));
      return fail();
    }
    walk(root, Matrix{});
    if (!diagnostics_.empty()) return fail();
    if (outlines_.empty()) {
      diagnostics_.push_back(base::Diagnostic::error(
          "SVG004",
          "no outline: the file has no polygon, polyline, line, rect, circle, ellipse or path",
          base::Span::whole(source_.name())));
      return fail();
    }
    return base::Result<std::vector<SvgOutline>>(std::move(outlines_));
  }

 private:
  base::Result<std::vector<SvgOutline>> fail() {
    return base::Result<std::vector<SvgOutline>>::failure(std::move(diagnostics_));
  }

  void error(const char* code, std::string message, std::size_t offset) {
    const auto [line, col] = source_.locate(offset);
    diagnostics_.push_back(base::Diagnostic::error(code, std::move(message),
                                                   base::Span::at(source_.name(), line, col)));
  }

  void walk(const pugi::xml_node& node, const Matrix& outer) {
    for (const pugi::xml_node& child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      if (!diagnostics_.empty()) return;
      std::optional<Matrix> own = transform(child);
      if (!own) return;
      const Matrix m = own->then(outer);
      const std::string_view tag = child.name();
      if (tag == "g" || tag == "svg" || tag == "a") {
        walk(child, m);
      } else if (tag == "polygon" || tag == "polyline") {
        std::vector<double> xy;
        if (!numbers(child, child.attribute("points").value(), xy)) return;
        if (xy.size() % 2 != 0) {
          error("SVG003", "odd number of coordinates in points", offset(child));
          return;
        }
        std::vector<Vec2> pts;
        for (std::size_t i = 0; i + 1 < xy.size(); i += 2) pts.push_back({xy[i], xy[i + 1]});
        add(child, m, std::move(pts), tag == "polygon");
      } else if (tag == "line") {
        std::vector<double> v(4);
        const char* names[] = {"x1", "y1", "x2", "y2"};
        for (int i = 0; i < 4; ++i)
          if (!length(child, names[i], v[static_cast<std::size_t>(i)])) return;
        add(child, m, {{v[0], v[1]}, {v[2], v[3]}}, false);
      } else if (tag == "rect") {
        double x = 0, y = 0, w = 0, h = 0;
        if (!length(child, "x", x) || !length(child, "y", y) || !length(child, "width", w) ||
            !length(child, "height", h))
          return;
        add(child, m, {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}, true);
      } else if (tag == "circle" || tag == "ellipse") {
        double cx = 0, cy = 0, rx = 0, ry = 0;
        const bool circle = tag == "circle";
        if (!length(child, "cx", cx) || !length(child, "cy", cy) ||
            !length(child, circle ? "r" : "rx", rx) || !length(child, circle ? "r" : "ry", ry))
          return;
        std::vector<Vec2> pts;
        for (int k = 0; k < kRoundSegments; ++k) {
          const double t = 2 * std::numbers::pi * k / kRoundSegments;
          pts.push_back({cx + rx * std::cos(t), cy + ry * std::sin(t)});
        }
        if (rx > 0 && ry > 0) add(child, m, std::move(pts), true);
      } else if (tag == "path") {
        path(child, m);
      }
    }
  }

  static std::size_t offset(const pugi::xml_node& node) {
    return static_cast<std::size_t>(std::max<std::ptrdiff_t>(node.offset_debug(), 0));
  }

  void add(const pugi::xml_node& node, const Matrix& m, std::vector<Vec2> points, bool closed) {
    SvgOutline o;
    o.id = node.attribute("id").value();
    ++count_;
    if (o.id.empty()) o.id = std::string(node.name()) + "#" + std::to_string(count_);
    for (Vec2& p : points) p = m.apply(p);
    if (closed && points.size() > 1 && points.front().x == points.back().x &&
        points.front().y == points.back().y)
      points.pop_back();
    if (points.size() < 2) return;
    o.points = std::move(points);
    o.closed = closed;
    outlines_.push_back(std::move(o));
  }

  // Numbers separated by commas and white space (SVG's number lists).
  bool numbers(const pugi::xml_node& node, const char* text, std::vector<double>& out) {
    const char* p = text;
    while (*p != '\0') {
      while (*p == ',' || std::isspace(static_cast<unsigned char>(*p)) != 0) ++p;
      if (*p == '\0') break;
      char* end = nullptr;
      const double v = std::strtod(p, &end);
      if (end == p || !std::isfinite(v)) {
        error("SVG003", std::string("malformed number in '") + text + "'", offset(node));
        return false;
      }
      out.push_back(v);
      p = end;
    }
    return true;
  }

  bool length(const pugi::xml_node& node, const char* name, double& out) {
    const pugi::xml_attribute a = node.attribute(name);
    if (!a) {
      out = 0;
      return true;
    }
    char* end = nullptr;
    out = std::strtod(a.value(), &end);
    const std::string_view rest(end);
    if (end == a.value() || !std::isfinite(out) || !(rest.empty() || rest == "px")) {
      error(
          "SVG003",
          std::string("attribute ") + name + "=\"" + a.value() + "\" is not a number in user units",
          offset(node));
      return false;
    }
    return true;
  }

  std::optional<Matrix> transform(const pugi::xml_node& node) {
    Matrix m;
    const std::string text = node.attribute("transform").value();
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() &&
             (std::isspace(static_cast<unsigned char>(text[i])) != 0 || text[i] == ','))
        ++i;
      if (i >= text.size()) break;
      const std::size_t open = text.find('(', i);
      const std::size_t close = text.find(')', i);
      if (open == std::string::npos || close == std::string::npos || close < open) {
        error("SVG003", "malformed transform '" + text + "'", offset(node));
        return std::nullopt;
      }
      std::string name = text.substr(i, open - i);
      while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back())) != 0)
        name.pop_back();
      std::vector<double> v;
      const std::string args = text.substr(open + 1, close - open - 1);
      if (!numbers(node, args.c_str(), v)) return std::nullopt;
      Matrix step;
      const auto need = [&](std::size_t lo, std::size_t hi) {
        if (v.size() < lo || v.size() > hi) {
          error("SVG003",
                "transform " + name + " takes " + std::to_string(lo) + " to " + std::to_string(hi) +
                    " numbers",
                offset(node));
          return false;
        }
        return true;
      };
      const double rad = std::numbers::pi / 180;
      if (name == "matrix") {
        if (!need(6, 6)) return std::nullopt;
        step = {v[0], v[1], v[2], v[3], v[4], v[5]};
      } else if (name == "translate") {
        if (!need(1, 2)) return std::nullopt;
        step.e = v[0];
        step.f = v.size() > 1 ? v[1] : 0;
      } else if (name == "scale") {
        if (!need(1, 2)) return std::nullopt;
        step.a = v[0];
        step.d = v.size() > 1 ? v[1] : v[0];
      } else if (name == "rotate") {
        if (!need(1, 3) || v.size() == 2) return std::nullopt;
        const double c = std::cos(v[0] * rad);
        const double s = std::sin(v[0] * rad);
        const double cx = v.size() == 3 ? v[1] : 0;
        const double cy = v.size() == 3 ? v[2] : 0;
        step = {c, s, -s, c, cx - c * cx + s * cy, cy - s * cx - c * cy};
      } else if (name == "skewX") {
        if (!need(1, 1)) return std::nullopt;
        step.c = std::tan(v[0] * rad);
      } else if (name == "skewY") {
        if (!need(1, 1)) return std::nullopt;
        step.b = std::tan(v[0] * rad);
      } else {
        error("SVG003", "unknown transform '" + name + "'", offset(node));
        return std::nullopt;
      }
      m = step.then(m);  // the leftmost transform is applied last
      i = close + 1;
    }
    return m;
  }

  // Path data: one outline per subpath.
  void path(const pugi::xml_node& node, const Matrix& m) {
    const std::string d = node.attribute("d").value();
    std::size_t i = 0;
    char command = 0;
    Vec2 at{}, start{}, control{};
    char last = 0;
    std::vector<Vec2> pts;
    const auto flush = [&](bool closed) {
      if (pts.size() >= 2) add(node, m, pts, closed);
      pts.clear();
    };
    const auto number = [&](double& out) {
      while (i < d.size() && (std::isspace(static_cast<unsigned char>(d[i])) != 0 || d[i] == ','))
        ++i;
      char* end = nullptr;
      out = std::strtod(d.c_str() + i, &end);
      if (end == d.c_str() + i || !std::isfinite(out)) {
        error("SVG003", "malformed path data near '" + d.substr(i, 12) + "'", offset(node));
        return false;
      }
      i = static_cast<std::size_t>(end - d.c_str());
      return true;
    };
    const auto point = [&](bool relative, Vec2& out) {
      double x = 0, y = 0;
      if (!number(x) || !number(y)) return false;
      out = relative ? Vec2{at.x + x, at.y + y} : Vec2{x, y};
      return true;
    };
    while (true) {
      while (i < d.size() && (std::isspace(static_cast<unsigned char>(d[i])) != 0 || d[i] == ','))
        ++i;
      if (i >= d.size()) break;
      if (std::isalpha(static_cast<unsigned char>(d[i])) != 0) {
        command = d[i++];
      } else if (command == 0) {
        error("SVG003", "path data must start with a command", offset(node));
        return;
      } else if (command == 'M') {
        command = 'L';
      } else if (command == 'm') {
        command = 'l';
      }
      const bool rel = std::islower(static_cast<unsigned char>(command)) != 0;
      const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
      Vec2 p{}, c1{}, c2{};
      switch (upper) {
        case 'M':
          flush(false);
          if (!point(rel, p)) return;
          at = start = p;
          pts.push_back(p);
          break;
        case 'L':
          if (!point(rel, p)) return;
          at = p;
          pts.push_back(p);
          break;
        case 'H': {
          double x = 0;
          if (!number(x)) return;
          at.x = rel ? at.x + x : x;
          pts.push_back(at);
          break;
        }
        case 'V': {
          double y = 0;
          if (!number(y)) return;
          at.y = rel ? at.y + y : y;
          pts.push_back(at);
          break;
        }
        case 'Z':
          flush(true);
          at = start;
          break;
        case 'C':
        case 'S':
        case 'Q':
        case 'T': {
          const bool smooth = upper == 'S' || upper == 'T';
          const bool cubic = upper == 'C' || upper == 'S';
          const bool follows = cubic ? (last == 'C' || last == 'S') : (last == 'Q' || last == 'T');
          c1 = smooth ? (follows ? Vec2{2 * at.x - control.x, 2 * at.y - control.y} : at) : Vec2{};
          if (!smooth && !point(rel, c1)) return;
          if (cubic && !point(rel, c2)) return;
          if (!point(rel, p)) return;
          if (pts.empty()) pts.push_back(at);
          const Vec2 from = at;
          for (int k = 1; k <= kCurveSegments; ++k) {
            const double t = static_cast<double>(k) / kCurveSegments;
            const double u = 1 - t;
            Vec2 q;
            if (cubic) {
              q = {u * u * u * from.x + 3 * u * u * t * c1.x + 3 * u * t * t * c2.x +
                       t * t * t * p.x,
                   u * u * u * from.y + 3 * u * u * t * c1.y + 3 * u * t * t * c2.y +
                       t * t * t * p.y};
            } else {
              q = {u * u * from.x + 2 * u * t * c1.x + t * t * p.x,
                   u * u * from.y + 2 * u * t * c1.y + t * t * p.y};
            }
            pts.push_back(q);
          }
          control = cubic ? c2 : c1;
          at = p;
          break;
        }
        case 'A': {
          double arc[5] = {0, 0, 0, 0, 0};  // rx, ry, x-axis rotation, large-arc, sweep
          for (double& v : arc)
            if (!number(v)) return;
          if (!point(rel, p)) return;
          if (pts.empty()) pts.push_back(at);
          elliptic_arc(at, p, arc, pts);
          at = p;
          break;
        }
        default:
          error("SVG003", std::string("unknown path command '") + command + "'", offset(node));
          return;
      }
      last = upper;
    }
    flush(false);
  }

  base::Source source_;
  std::vector<base::Diagnostic> diagnostics_;
  std::vector<SvgOutline> outlines_;
  std::size_t count_ = 0;
};

}  // namespace

base::Result<std::vector<SvgOutline>> read_svg(std::string_view text,
                                               const std::string& source_name) {
  return Reader(text, source_name).run();
}

}  // namespace insula::io
