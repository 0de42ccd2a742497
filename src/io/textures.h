// The image files a grammar's texture() / set(material.colormap, ...) names (shape::Material::
// texture), found as assets are (io::AssetSearch, docs/assets.md) and read: PNG and JPEG, decoded
// for the renderer and kept as they are for writers that embed or copy them.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/asset_search.h"
#include "shape/scene.h"

namespace insula::io {

struct TextureFailure {
  std::string name;   // as the grammar wrote it
  std::string error;  // "not found (looked in ...)", "not a PNG or JPEG image"
};

// The file a texture name denotes, or nullopt with `error` set ("not found (looked in ...)").
using TextureResolver =
    std::function<std::optional<std::filesystem::path>(std::string_view name, std::string& error)>;

// Sets Material::image of every material with a texture it can find and read; the others keep
// their colour only. Returns one failure per texture name that could not be had.
std::vector<TextureFailure> load_textures(shape::Scene& scene, const TextureResolver& resolve);
// Textures found as CGA assets are (AssetSearch).
std::vector<TextureFailure> load_textures(shape::Scene& scene, const AssetSearch& search);

// The texture of an image file's bytes: decoded RGBA plus the bytes and their MIME type; null
// with `error` set when they are not a PNG or JPEG image this build decodes.
std::shared_ptr<const shape::Image> decode_texture(std::string name, std::string bytes,
                                                   std::string& error);

}  // namespace insula::io
