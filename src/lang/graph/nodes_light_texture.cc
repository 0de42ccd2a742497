// Lights and textures (graph-format.md §11 "Lights and textures"; docs/graph-executor.md): light
// sources placed in their actor's scope, and procedural RGBA images (seed 003 §5.1: "text on
// image", texture synthesis by inversion and combination) that shape.set_texture puts on faces.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "base/bitmap_font.h"
#include "lang/graph/nodes.h"
#include "lang/graph/properties.h"

namespace insula::lang::graph {
namespace {

// Images bigger than this per side are refused (the PNG view's limit too): a typo such as
// width 25600 would otherwise allocate gigabytes.
constexpr std::int64_t kMaxTextureSide = 8192;

std::string vec_text(kernel::Vec3 v) {
  std::string out(1, '[');
  out += to_string(Value(v.x));
  out += ", ";
  out += to_string(Value(v.y));
  out += ", ";
  out += to_string(Value(v.z));
  out += ']';
  return out;
}

bool unit_colour(kernel::Vec3 c) {
  const auto in = [](double v) { return v >= 0 && v <= 1; };
  return in(c.x) && in(c.y) && in(c.z);
}

// A colour in [0, 1] as 8-bit channels, stored as given (glTF reads base colour textures as sRGB).
std::array<std::uint8_t, 4> bytes(kernel::Vec3 c) {
  const auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(v * 255)); };
  return {byte(c.x), byte(c.y), byte(c.z), 255};
}

void create_light(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId actor = c.current(r);
    // Meaningful in the actor's scope: vec(sx()/2, sy(), sz()/2) is a mass's top centre whatever
    // its orientation. A point's or light's scope is the point itself.
    const std::optional<shape::Scope> scope = entity_scope(c.entities(), c.tree(), actor);
    if (!scope) c.error("a light needs an actor with a scope");
    const kernel::Vec3 local = c.param(r, "position").vec();
    auto light = std::make_shared<LightData>();
    light->kind = c.param(r, "kind").text();
    light->intensity = c.param(r, "intensity").number();
    light->color = c.param(r, "color").vec();
    light->range = c.param(r, "range").number();
    if (!unit_colour(light->color)) {
      c.fail(actor, "light colour components must lie in [0, 1]; got " + vec_text(light->color));
      continue;
    }
    const EntityId e = c.entities().derive(actor, EntityType::kLight);
    c.entities()[e].position = scope->to_world(local);
    c.entities()[e].light = std::move(light);
    c.emit(c.output_port("out"), e);
  }
}

// The text is set in the bitmap font (base/bitmap_font.h) and scaled by size / 8 with nearest
// neighbour sampling at pixel centres, so one font dot is size / 8 pixels square; the block of
// lines is centred in the image and clipped by it.
void paint_text(Texture& t, const std::string& text, double size, std::array<std::uint8_t, 4> ink) {
  const base::TextMask mask = base::text_mask(text);
  if (mask.width == 0 || size <= 0) return;
  const double scale = size / base::kGlyphHeight;
  const double left = (t.width - mask.width * scale) / 2;
  const double top = (t.height - mask.height * scale) / 2;
  for (int y = 0; y < t.height; ++y) {
    const double v = std::floor((y + 0.5 - top) / scale);
    if (v < 0 || v >= mask.height) continue;
    for (int x = 0; x < t.width; ++x) {
      const double u = std::floor((x + 0.5 - left) / scale);
      if (u < 0 || u >= mask.width || !mask.at(static_cast<int>(u), static_cast<int>(v))) continue;
      const std::size_t i = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(t.width) +
                                 static_cast<std::size_t>(x));
      std::copy(ink.begin(), ink.end(), t.rgba.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }
}

void text(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const std::int64_t width = c.param(r, "width").integer();
    const std::int64_t height = c.param(r, "height").integer();
    if (width > kMaxTextureSide || height > kMaxTextureSide) {
      c.error("a texture is at most " + std::to_string(kMaxTextureSide) + " x " +
              std::to_string(kMaxTextureSide) + " pixels; got " + std::to_string(width) + " x " +
              std::to_string(height));
    }
    const kernel::Vec3 color = c.param(r, "color").vec();
    const kernel::Vec3 background = c.param(r, "background").vec();
    const EntityId e = c.create(r, EntityType::kTexture, 0);
    if (!unit_colour(color) || !unit_colour(background)) {
      c.fail(e, "texture colours must lie in [0, 1]; got color " + vec_text(color) +
                    ", background " + vec_text(background));
      continue;
    }
    auto t = std::make_shared<Texture>();
    t->name = c.param(r, "name").text();
    t->text = c.param(r, "text").text();
    t->width = static_cast<int>(width);
    t->height = static_cast<int>(height);
    const std::array<std::uint8_t, 4> paper = bytes(background);
    t->rgba.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    for (std::size_t i = 0; i < t->rgba.size(); i += 4) {
      std::copy(paper.begin(), paper.end(), t->rgba.begin() + static_cast<std::ptrdiff_t>(i));
    }
    paint_text(*t, t->text, c.param(r, "size").number(), bytes(color));
    c.entities()[e].texture = std::move(t);
    c.emit(c.output_port("out"), e);
  }
}

// Derived textures get names of their own: shape.set_texture names its material after the
// texture, so an inverted copy must not share its source's material.
void invert(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    auto t = std::make_shared<Texture>(*c.entities()[in].texture);
    t->name += "_inverted";
    for (std::size_t i = 0; i < t->rgba.size(); ++i) {
      if (i % 4 != 3) t->rgba[i] = static_cast<std::uint8_t>(255 - t->rgba[i]);
    }
    const EntityId e = c.entities().derive(in, EntityType::kTexture);
    c.entities()[e].texture = std::move(t);
    c.emit(c.output_port("out"), e);
  }
}

std::uint8_t combine_channel(std::string_view op, int a, int b) {
  int v = (a * b + 127) / 255;  // multiply: 255 is one, rounded to nearest
  if (op == "add") v = a + b;
  if (op == "subtract") v = a - b;
  return static_cast<std::uint8_t>(std::clamp(v, 0, 255));
}

// Red, green and blue combine; alpha is a's, so subtracting two opaque images stays opaque.
void combine(NodeContext& c) {
  const std::size_t port_b = c.input_port("b");
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId a = c.current(r);
    const EntityId b = c.input(r, port_b).front();
    const Texture& ta = *c.entities()[a].texture;
    const Texture& tb = *c.entities()[b].texture;
    if (ta.width != tb.width || ta.height != tb.height) {
      c.fail(a, "texture.combine needs textures of one size; '" + ta.name + "' is " +
                    std::to_string(ta.width) + " x " + std::to_string(ta.height) + ", '" + tb.name +
                    "' is " + std::to_string(tb.width) + " x " + std::to_string(tb.height));
      continue;
    }
    const std::string op = c.param(r, "op").text();
    auto t = std::make_shared<Texture>(ta);
    t->name = ta.name + "_" + op + "_" + tb.name;
    if (!tb.text.empty()) t->text += (t->text.empty() ? "" : "\n") + tb.text;
    for (std::size_t i = 0; i < t->rgba.size(); ++i) {
      if (i % 4 != 3) t->rgba[i] = combine_channel(op, ta.rgba[i], tb.rgba[i]);
    }
    const EntityId e = c.entities().derive(a, EntityType::kTexture);
    c.entities()[e].texture = std::move(t);
    c.emit(c.output_port("out"), e);
  }
}

constexpr NodeImpl kNodes[] = {
    {"light.create", create_light},
    {"texture.text", text},
    {"texture.invert", invert},
    {"texture.combine", combine},
};

}  // namespace

std::span<const NodeImpl> light_texture_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
