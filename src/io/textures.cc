#include "io/textures.h"

#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>

// stb_image's implementation lives in this translation unit only, with static linkage (as
// png_renderer.cc does for stb_image_write), limited to the two formats textures use. Its header
// is a system header: its own warnings are not ours.
#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace insula::io {

namespace {

constexpr int kMaxTextureSide = 16384;

std::string mime_of(const std::string& bytes) {
  if (bytes.starts_with("\x89PNG\r\n\x1a\n")) return "image/png";
  if (bytes.starts_with("\xff\xd8\xff")) return "image/jpeg";
  return {};
}

}  // namespace

std::shared_ptr<const shape::Image> decode_texture(std::string name, std::string bytes,
                                                   std::string& error) {
  const std::string mime = mime_of(bytes);
  if (mime.empty()) {
    error = "not a PNG or JPEG image";
    return nullptr;
  }
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels =
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                            static_cast<int>(bytes.size()), &width, &height, &channels, 4);
  if (pixels == nullptr || width <= 0 || height <= 0 || width > kMaxTextureSide ||
      height > kMaxTextureSide) {
    if (pixels != nullptr) stbi_image_free(pixels);
    error = "cannot decode the image (" + std::string(mime) + ")";
    return nullptr;
  }
  auto image = std::make_shared<shape::Image>();
  image->name = std::move(name);
  image->width = width;
  image->height = height;
  image->rgba.assign(
      pixels, pixels + 4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  stbi_image_free(pixels);
  image->encoded = std::move(bytes);
  image->mime_type = mime;
  return image;
}

std::vector<TextureFailure> load_textures(shape::Scene& scene, const TextureResolver& resolve) {
  std::vector<TextureFailure> failures;
  std::map<std::string, std::shared_ptr<const shape::Image>, std::less<>> loaded;
  for (shape::Material& material : scene.materials) {
    if (material.texture.empty() || material.image != nullptr) continue;
    auto [it, added] = loaded.try_emplace(material.texture, nullptr);
    if (added) {
      std::string error;
      if (const auto file = resolve(material.texture, error)) {
        std::ifstream in(*file, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (in.bad()) {
          error = std::string("cannot read '").append(file->string()).append("'");
        } else {
          const std::string name = file->filename().string();
          it->second = decode_texture(name, std::move(bytes), error);
          if (!error.empty())
            error = std::string("'").append(file->string()).append("': ").append(error);
        }
      }
      if (!error.empty()) failures.push_back({material.texture, error});
    }
    material.image = it->second;
  }
  return failures;
}

std::vector<TextureFailure> load_textures(shape::Scene& scene, const AssetSearch& search) {
  return load_textures(
      scene,
      [&](std::string_view name, std::string& error) -> std::optional<std::filesystem::path> {
        std::optional<std::filesystem::path> file = search.resolve(name);
        if (!file) {
          std::string places;
          for (const auto& p : search.candidates(name)) {
            places.append(places.empty() ? "" : ", ").append(p.string());
          }
          error = std::string("not found (looked in ").append(places).append(")");
        }
        return file;
      });
}

}  // namespace insula::io
