#include "io/file_functions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

namespace insula::io {

namespace fs = std::filesystem;

namespace {

// A workspace of many projects stays bounded: fileSearch lists at most this many files.
constexpr std::size_t kMaxListed = 200000;

// '*' matches any run of characters ('/' included, as CityEngine's queries do), '?' one.
bool glob_match(std::string_view pattern, std::string_view text) {
  std::size_t p = 0, t = 0, star = std::string_view::npos, resume = 0;
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++p;
      ++t;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = t;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      t = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::string relative_or_empty(const fs::path& file, const fs::path& base) {
  const auto [b, f] = std::mismatch(base.begin(), base.end(), file.begin(), file.end());
  if (b != base.end()) return {};
  fs::path rest;
  for (auto it = f; it != file.end(); ++it) rest /= *it;
  return rest.generic_string();
}

bool is_project(const fs::path& folder) {
  std::error_code ec;
  return fs::is_directory(folder / "assets", ec) || fs::is_directory(folder / "rules", ec) ||
         fs::is_regular_file(folder / ".project", ec);
}

// Regular files under `root`, hidden folders (.git, CityEngine's .settings) left out.
void walk(const fs::path& root, std::vector<fs::path>& out) {
  std::error_code ec;
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (out.size() >= kMaxListed) return;
    const std::string name = it->path().filename().string();
    std::error_code type_error;
    if (it->is_directory(type_error)) {
      if (!name.empty() && name.front() == '.') it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file(type_error)) out.push_back(it->path().lexically_normal());
  }
}

// One term of a query, against one file.
class Term {
 public:
  static std::optional<Term> parse(std::string_view text, std::string& error) {
    Term t;
    for (std::string_view key : {"Name=", "Ext=", "Project=", "Path="}) {
      if (text.substr(0, key.size()) == key) {
        t.property_ = std::string(key.substr(0, key.size() - 1));
        t.pattern_ = std::string(text.substr(key.size()));
        return t;
      }
    }
    t.pattern_ = std::string(text);
    if (!text.empty() && text.front() == '$') {
      try {
        t.regex_.emplace(std::string(text.substr(1)));
      } catch (const std::regex_error& e) {
        error = "fileSearch: invalid regular expression '" + std::string(text.substr(1)) +
                "': " + e.what();
        return std::nullopt;
      }
    }
    return t;
  }

  template <typename Listed>
  bool matches(const Listed& f) const {
    if (property_ == "Name") return glob_match(pattern_, f.path.filename().string());
    if (property_ == "Ext") {
      const std::string ext = f.path.extension().string();
      return glob_match(pattern_, ext.empty() ? ext : ext.substr(1));
    }
    if (property_ == "Project") return glob_match(pattern_, f.project);
    if (property_ == "Path") return glob_match(pattern_, f.name);
    const bool rooted = pattern_.size() > (regex_ ? 1U : 0U) && pattern_[regex_ ? 1 : 0] == '/';
    const std::string in_workspace =
        f.in_workspace.empty() ? std::string() : (rooted ? "/" : "") + f.in_workspace;
    for (const std::string* text : {&f.in_assets, &f.in_project, &in_workspace}) {
      if (text->empty()) continue;
      if (regex_ ? std::regex_match(*text, *regex_) : glob_match(pattern_, *text)) return true;
    }
    return false;
  }

 private:
  std::string property_;
  std::string pattern_;
  std::optional<std::regex> regex_;
};

std::uint32_t read_u32(const unsigned char* p, bool little) {
  return little ? (p[0] | p[1] << 8 | p[2] << 16 | static_cast<std::uint32_t>(p[3]) << 24)
                : (static_cast<std::uint32_t>(p[0]) << 24 | p[1] << 16 | p[2] << 8 | p[3]);
}
std::uint32_t read_u16(const unsigned char* p, bool little) {
  return little ? static_cast<std::uint32_t>(p[0] | p[1] << 8)
                : static_cast<std::uint32_t>(p[0] << 8 | p[1]);
}

// The first `n` bytes of a file (fewer when it is shorter).
std::string head_bytes(const fs::path& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(n));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return bytes;
}

const unsigned char* bytes_of(const std::string& s, std::size_t at) {
  return reinterpret_cast<const unsigned char*>(s.data()) + at;
}

std::optional<ImageSize> checked(std::int64_t width, std::int64_t height) {
  if (width <= 0 || height <= 0 || width > INT32_MAX || height > INT32_MAX) return std::nullopt;
  return ImageSize{static_cast<int>(width), static_cast<int>(height)};
}

// PNG: the IHDR chunk right after the signature holds width and height (big-endian).
std::optional<ImageSize> png_size(const std::string& h) {
  if (h.size() < 24 || h.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || h.compare(12, 4, "IHDR") != 0) {
    return std::nullopt;
  }
  return checked(read_u32(bytes_of(h, 16), false), read_u32(bytes_of(h, 20), false));
}

// BMP: width and height (negative for top-down rows) at bytes 18 and 22 (little-endian).
std::optional<ImageSize> bmp_size(const std::string& h) {
  if (h.size() < 26 || h.compare(0, 2, "BM") != 0) return std::nullopt;
  const auto width = static_cast<std::int32_t>(read_u32(bytes_of(h, 18), true));
  const auto height = static_cast<std::int32_t>(read_u32(bytes_of(h, 22), true));
  return checked(width, std::abs(static_cast<std::int64_t>(height)));
}

// JPEG: the segments after SOI up to the first start-of-frame marker (C0-CF except DHT C4, JPG
// C8, DAC CC), whose payload is precision, height, width.
std::optional<ImageSize> jpeg_size(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 2> soi{};
  if (!in.read(reinterpret_cast<char*>(soi.data()), 2) || soi[0] != 0xFF || soi[1] != 0xD8) {
    return std::nullopt;
  }
  while (in) {
    int c = in.get();
    if (c != 0xFF) return std::nullopt;
    while (c == 0xFF) c = in.get();  // fill bytes
    if (c == EOF) return std::nullopt;
    if (c == 0x01 || (c >= 0xD0 && c <= 0xD7)) continue;  // markers without a length
    std::array<unsigned char, 7> seg{};
    if (!in.read(reinterpret_cast<char*>(seg.data()), 2)) return std::nullopt;
    const std::uint32_t length = read_u16(seg.data(), false);
    if (length < 2) return std::nullopt;
    if (c >= 0xC0 && c <= 0xCF && c != 0xC4 && c != 0xC8 && c != 0xCC) {
      if (length < 7 || !in.read(reinterpret_cast<char*>(seg.data() + 2), 5)) return std::nullopt;
      return checked(read_u16(&seg[5], false), read_u16(&seg[3], false));
    }
    in.seekg(length - 2, std::ios::cur);
  }
  return std::nullopt;
}

// TIFF (CityEngine's asset library ships .tif textures): the ImageWidth (256) and ImageLength
// (257) entries of the first image file directory.
std::optional<ImageSize> tiff_size(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 8> head{};
  if (!in.read(reinterpret_cast<char*>(head.data()), 8)) return std::nullopt;
  const bool little = head[0] == 'I' && head[1] == 'I';
  if (!little && !(head[0] == 'M' && head[1] == 'M')) return std::nullopt;
  if (read_u16(&head[2], little) != 42) return std::nullopt;
  in.seekg(read_u32(&head[4], little));
  std::array<unsigned char, 2> count{};
  if (!in.read(reinterpret_cast<char*>(count.data()), 2)) return std::nullopt;
  std::int64_t width = 0, height = 0;
  for (std::uint32_t k = 0; k < read_u16(count.data(), little); ++k) {
    std::array<unsigned char, 12> e{};
    if (!in.read(reinterpret_cast<char*>(e.data()), 12)) return std::nullopt;
    const std::uint32_t tag = read_u16(&e[0], little);
    const std::uint32_t type = read_u16(&e[2], little);
    const std::uint32_t value = type == 3 ? read_u16(&e[8], little) : read_u32(&e[8], little);
    if (tag == 256) width = value;
    if (tag == 257) height = value;
  }
  return checked(width, height);
}

}  // namespace

std::optional<ImageSize> read_image_size(const fs::path& path) {
  const std::string head = head_bytes(path, 26);
  if (auto size = png_size(head)) return size;
  if (auto size = bmp_size(head)) return size;
  if (head.size() >= 2 && head.compare(0, 2, "\xFF\xD8") == 0) return jpeg_size(path);
  return tiff_size(path);
}

bool FileFunctions::file_exists(std::string_view path) const {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = exists_.find(path); it != exists_.end()) return it->second;
  }
  const bool exists = search_.resolve(path).has_value();  // outside the lock: it reads folders
  const std::lock_guard<std::mutex> lock(mutex_);
  exists_.emplace(std::string(path), exists);
  return exists;
}

const std::vector<FileFunctions::Listed>& FileFunctions::listing() const {
  std::call_once(listed_, [this] {
    const fs::path own = search_.project().value_or(search_.folder());
    std::vector<fs::path> roots = {own};
    std::error_code ec;
    for (fs::directory_iterator it(search_.workspace(), ec), end; !ec && it != end;
         it.increment(ec)) {
      const fs::path p = it->path().lexically_normal();
      if (p != own && is_project(p)) roots.push_back(p);
    }
    std::vector<fs::path> paths;
    for (const fs::path& root : roots) walk(root, paths);
    std::sort(paths.begin(), paths.end());
    paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
    for (const fs::path& p : paths) {
      Listed f;
      f.path = p;
      f.name = search_.workspace_name(p);
      f.in_project = relative_or_empty(p, own);
      f.in_assets = search_.project() ? relative_or_empty(p, *search_.project() / "assets") : "";
      f.in_workspace = relative_or_empty(p, search_.workspace());
      const std::string& top = f.in_workspace.empty() ? f.in_project : f.in_workspace;
      f.project = f.in_workspace.empty() ? own.filename().string() : top.substr(0, top.find('/'));
      files_.push_back(std::move(f));
    }
  });
  return files_;
}

std::string FileFunctions::file_search(std::string_view query, std::string& error) const {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = searches_.find(query); it != searches_.end()) return it->second;
  }
  std::vector<Term> terms;
  std::istringstream words{std::string(query)};
  for (std::string word; words >> word;) {
    std::optional<Term> term = Term::parse(word, error);
    if (!term) return {};
    terms.push_back(std::move(*term));
  }
  std::set<std::string> names;  // sorted, as CityEngine sorts
  if (!terms.empty()) {
    for (const Listed& f : listing()) {
      const bool all =
          std::all_of(terms.begin(), terms.end(), [&](const Term& t) { return t.matches(f); });
      if (all) names.insert(f.name);
    }
  }
  std::string list;
  for (const std::string& name : names) list += name + ";";
  const std::lock_guard<std::mutex> lock(mutex_);
  searches_.emplace(std::string(query), list);
  return list;
}

std::string FileFunctions::file_random(std::string_view query, double random,
                                       std::string& error) const {
  const std::string list = file_search(query, error);
  const auto count = static_cast<std::size_t>(std::count(list.begin(), list.end(), ';'));
  if (count == 0) return {};
  const double r = std::isfinite(random) ? std::clamp(random, 0.0, 1.0) : 0.0;
  const std::size_t pick =
      std::min(count - 1, static_cast<std::size_t>(r * static_cast<double>(count)));
  std::size_t start = 0;
  for (std::size_t k = 0; k < pick; ++k) start = list.find(';', start) + 1;
  return list.substr(start, list.find(';', start) - start);
}

std::optional<double> FileFunctions::asset_info(std::string_view path, std::string_view attribute,
                                                std::string& error) const {
  static constexpr std::array<std::string_view, 6> kNames = {"sx", "sy", "sz", "tx", "ty", "tz"};
  const auto at = std::find(kNames.begin(), kNames.end(), attribute);
  if (at == kNames.end()) {
    error = "assetInfo: unknown attribute '" + std::string(attribute) +
            "' (expected sx, sy, sz, tx, ty or tz)";
    return std::nullopt;
  }
  const std::shared_ptr<const ImportedAsset> asset = assets_.asset(path, error);
  if (!asset) return std::nullopt;
  const kernel::Bounds3 b = asset->mesh.bounds();
  const kernel::Vec3 size = b.size();
  const std::array<double, 6> values = {size.x, size.y, size.z, b.min.x, b.min.y, b.min.z};
  return values[static_cast<std::size_t>(at - kNames.begin())];
}

std::optional<double> FileFunctions::image_info(std::string_view path, std::string_view attribute,
                                                std::string& error) const {
  if (attribute != "sx" && attribute != "sy") {
    error = "imageInfo: unknown attribute '" + std::string(attribute) + "' (expected sx or sy)";
    return std::nullopt;
  }
  const std::optional<fs::path> file = search_.resolve(path);
  if (!file) {
    error = "image '" + std::string(path) + "' not found";
    return std::nullopt;
  }
  std::optional<ImageSize> size;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    auto it = images_.find(*file);
    if (it == images_.end()) it = images_.emplace(*file, read_image_size(*file)).first;
    size = it->second;
  }
  if (!size) {
    error = "image '" + std::string(path) + "': not an image this build reads";
    return std::nullopt;
  }
  return attribute == "sx" ? size->width : size->height;
}

std::optional<std::string> FileFunctions::read_text(std::string_view path,
                                                    std::string& error) const {
  const std::optional<fs::path> file = search_.resolve(path);
  if (!file) {
    error = "file '" + std::string(path) + "' not found";
    return std::nullopt;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  auto it = texts_.find(*file);
  if (it == texts_.end()) {
    std::ifstream in(*file, std::ios::binary);
    std::optional<std::string> text;
    if (in) {
      std::ostringstream bytes;
      bytes << in.rdbuf();
      text = bytes.str();
    }
    it = texts_.emplace(*file, std::move(text)).first;
  }
  if (!it->second) error = "cannot read '" + std::string(path) + "'";
  return it->second;
}

}  // namespace insula::io
