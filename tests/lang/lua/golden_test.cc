// Golden files of the Lua front-end, as the CGA and .bldg front-ends have them: every program of
// examples/lua/ runs (seed 0, its assets/ folder) and its result is summarised in
// tests/data/lua/golden/<stem>.txt: the tree (components, roots, operations, labels with their
// counts) and the collected scene (per part name: how many, faces, surface area, the closed ones
// and their volume, instances). Regenerate with INSULA_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "../../common/test_util.h"
#include "io/obj_reader.h"
#include "kernel/mesh.h"
#include "lang/lua/runtime.h"
#include "shape/scene.h"

namespace insula::lua {
namespace {

const std::filesystem::path kExamples = std::filesystem::path(INSULA_SOURCE_DIR) / "examples/lua";

// <name>.obj from one folder (the CLI's provider adds the sandbox checks, tested in lua_build.sh).
class FolderAssets : public shape::AssetProvider {
 public:
  explicit FolderAssets(std::filesystem::path folder) : folder_(std::move(folder)) {}
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override {
    const std::filesystem::path path = folder_ / (std::string(name) + ".obj");
    auto mesh = io::read_obj(test::read_file(path), path.string());
    if (!mesh.ok()) {
      error = "asset '" + std::string(name) + "' not found";
      return nullptr;
    }
    return std::make_shared<const kernel::Mesh>(std::move(mesh.value()));
  }

 private:
  std::filesystem::path folder_;
};

std::string fixed(double v) {
  char text[32];
  const double r = std::round(v * 1e4) / 1e4;
  std::snprintf(text, sizeof text, "%.4f", r == 0 ? 0.0 : r);
  return text;
}

std::string summary(Runtime& runtime) {
  const shape::ShapeTree& tree = runtime.tree();
  std::map<std::string, int> labels;
  std::size_t roots = 0;
  for (shape::ShapeId id = 0; id < tree.size(); ++id) {
    if (tree.parent(id) == shape::kNoShape) ++roots;
    for (const std::string_view label : tree.labels(id)) ++labels[std::string(label)];
  }
  std::string out = "components " + std::to_string(tree.size()) + " roots " +
                    std::to_string(roots) + " operations " +
                    std::to_string(runtime.stats().operations) + "\n";
  for (const auto& [label, count] : labels)
    out += "label " + label + " " + std::to_string(count) + "\n";
  const shape::Scene scene = collect_program(runtime.program());
  // Parts of one name summed (an apartment building has thousands): count, faces, area, and the
  // volume of the closed ones; instances count their shared mesh's faces.
  struct Sum {
    std::size_t count = 0, faces = 0, closed = 0, instances = 0;
    double area = 0, volume = 0;
  };
  for (const shape::Building& b : scene.buildings) {
    out += "building " + b.id + " parts " + std::to_string(b.parts.size()) + "\n";
    std::map<std::string, Sum> sums;
    for (const shape::Part& p : b.parts) {
      Sum& s = sums[p.name];
      ++s.count;
      if (p.instance_of) {
        ++s.instances;
        s.faces += p.instance_of->face_count();
        continue;
      }
      s.faces += p.mesh.face_count();
      s.area += kernel::surface_area(p.mesh);
      if (kernel::is_watertight(p.mesh)) {
        ++s.closed;
        s.volume += kernel::volume(p.mesh);
      }
    }
    for (const auto& [name, s] : sums) {
      out += "  " + name + " x" + std::to_string(s.count) + " faces " + std::to_string(s.faces) +
             " area " + fixed(s.area) + " closed " + std::to_string(s.closed) + " volume " +
             fixed(s.volume) + " instances " + std::to_string(s.instances) + "\n";
    }
  }
  return out;
}

TEST(LuaGolden, ExamplesMatchTheirGoldens) {
  const auto programs = test::files_in(kExamples, ".lua");
  ASSERT_GE(programs.size(), 5U);
  const FolderAssets assets(kExamples / "assets");
  for (const std::filesystem::path& path : programs) {
    SCOPED_TRACE(path.string());
    RunOptions options;
    options.assets = &assets;
    Runtime runtime(std::move(options));
    const auto diagnostics =
        runtime.run(base::Source(path.filename().string(), test::read_file(path)));
    ASSERT_TRUE(diagnostics.empty()) << base::render(diagnostics.front());
    test::expect_golden(std::filesystem::path(INSULA_TEST_DATA) / "lua" / "golden" /
                            (path.stem().string() + ".txt"),
                        summary(runtime));
  }
}

}  // namespace
}  // namespace insula::lua
