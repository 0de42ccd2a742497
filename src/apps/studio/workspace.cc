#include "apps/studio/workspace.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <random>
#include <string_view>
#include <system_error>

namespace insula::studio {
namespace fs = std::filesystem;

namespace {

constexpr std::array<std::string_view, 10> kExtensions = {
    ".cga", ".bldg", ".lua", ".psm", ".graph.json", ".geojson", ".json", ".osm", ".xml", ".obj"};

bool inside(const fs::path& root, const fs::path& path) {
  const auto [r, p] = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
  return r == root.end();
}

}  // namespace

bool is_studio_file(const fs::path& path) {
  const std::string name = path.filename().string();
  return std::any_of(kExtensions.begin(), kExtensions.end(), [&name](std::string_view ext) {
    return name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0;
  });
}

Workspace::Workspace(const fs::path& root) : root_(fs::canonical(root)) {}

std::optional<fs::path> Workspace::resolve(const std::string& relative, std::string& why) const {
  if (relative.empty()) {
    why = "no path";
    return std::nullopt;
  }
  // A NUL would end the name where the system reads it, after the checks read the whole.
  if (std::any_of(relative.begin(), relative.end(),
                  [](char c) { return static_cast<unsigned char>(c) < 0x20; })) {
    why = "a path with control characters";
    return std::nullopt;
  }
  const fs::path given(relative);
  if (given.is_absolute() || given.has_root_name() || given.has_root_directory()) {
    why = "an absolute path";
    return std::nullopt;
  }
  for (const fs::path& part : given) {
    if (part == "..") {
      why = "a path with '..'";
      return std::nullopt;
    }
  }
  // Symbolic links anywhere on the way are followed, then the result must still be inside.
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(root_ / given, error);
  if (error || !inside(root_, resolved) || resolved == root_) {
    why = resolved == root_ ? "the folder itself" : "a path leading out of the folder";
    return std::nullopt;
  }
  return resolved;
}

std::vector<Workspace::Entry> Workspace::files() const {
  std::vector<Entry> out;
  std::error_code error;
  fs::recursive_directory_iterator it(root_, fs::directory_options::skip_permission_denied, error);
  for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    const fs::path& path = it->path();
    const std::string name = path.filename().string();
    if (it->is_directory(error) && (name.starts_with(".") || name == "node_modules")) {
      it.disable_recursion_pending();
      continue;
    }
    if (name.starts_with(".") || !it->is_regular_file(error) || !is_studio_file(path)) continue;
    const fs::path real = fs::weakly_canonical(path, error);
    if (error || !inside(root_, real)) continue;  // a link leading out
    out.push_back({path.lexically_relative(root_).generic_string(), it->file_size(error)});
  }
  std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.path < b.path; });
  return out;
}

std::string Workspace::save(const fs::path& path, const std::string& text) {
  std::random_device random;
  // Appended, not `"." + name + ...`: GCC 12 warns falsely (-Wrestrict) on that chain.
  std::string name = ".";
  name.append(path.filename().string()).append(".studio-").append(std::to_string(random()));
  name.append(".tmp");
  const fs::path temporary = path.parent_path() / name;
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      return "cannot write " + path.filename().string();
    }
  }
  std::error_code error;
  // The file keeps its permissions (the temporary was made with the default ones).
  const fs::file_status before = fs::status(path, error);
  if (!error && fs::is_regular_file(before)) {
    fs::permissions(temporary, before.permissions(), error);
  }
  error.clear();
  fs::rename(temporary, path, error);
  if (error) {
    fs::remove(temporary, error);
    return "cannot replace " + path.filename().string();
  }
  return {};
}

}  // namespace insula::studio
