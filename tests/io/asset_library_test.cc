#include "io/asset_library.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "asset_fixtures.h"

namespace insula::io {
namespace {

using testing::TempFolder;
using testing::write_file;

TEST(AssetLibrary, ImportsOnceAndSharesAcrossThreads) {
  const TempFolder dir;
  write_file(dir / "rules" / "a.cga", "");
  write_file(dir / "assets" / "box.obj", testing::box_obj(1, 2, 3, "box.mtl"));
  write_file(dir / "assets" / "box.mtl", testing::kBoxMtl);
  const AssetSearch search(dir / "rules" / "a.cga");
  const AssetLibrary library(search, AssetLibrary::Missing::kNothing);
  std::vector<const kernel::Mesh*> seen(8);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t) {
    threads.emplace_back([&, t] {
      for (int k = 0; k < 200; ++k) {
        std::string error;
        seen[t] = library.find("box.obj", error).get();
      }
    });
  }
  for (std::thread& t : threads) t.join();
  for (const kernel::Mesh* m : seen) EXPECT_EQ(m, seen.front());
  ASSERT_NE(seen.front(), nullptr);
  EXPECT_EQ(seen.front()->face_count(), 6U);
  // The provider's mesh has no material ids (the scene's table does not know them); the
  // imported asset keeps them.
  for (std::size_t f = 0; f < seen.front()->face_count(); ++f) {
    EXPECT_EQ(seen.front()->tag(f).material, 0);
  }
  std::string error;
  const auto asset = library.asset("box.obj", error);
  ASSERT_TRUE(asset);
  EXPECT_EQ(asset->mesh.tag(0).material, 1);
  EXPECT_EQ(asset->materials.size(), 2U);
  EXPECT_TRUE(library.failures().empty());
}

// CityEngine inserts nothing for a missing asset: an empty mesh, and one failure per name with
// the number of requests, however many threads asked.
TEST(AssetLibrary, MissingAssetsAreCountedOncePerName) {
  const TempFolder dir;
  write_file(dir / "rules" / "a.cga", "");
  write_file(dir / "assets" / "bad.glb", "junk");
  const AssetSearch search(dir / "rules" / "a.cga");
  const AssetLibrary library(search, AssetLibrary::Missing::kNothing);
  std::atomic<int> empty{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      for (int k = 0; k < 50; ++k) {
        std::string error;
        const auto mesh = library.find(k % 2 == 0 ? "win.obj" : "bad.glb", error);
        if (mesh && mesh->empty() && error.empty()) ++empty;
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(empty.load(), 200);
  const std::vector<AssetLibrary::Failure> failures = library.failures();
  ASSERT_EQ(failures.size(), 2U);
  EXPECT_EQ(failures[0].name, "bad.glb");
  EXPECT_EQ(failures[0].count, 100U);
  EXPECT_EQ(failures[0].error.rfind("asset 'bad.glb': " + (dir / "assets" / "bad.glb").string() +
                                        ": error[AST001]: cannot read the asset",
                                    0),
            0U)
      << failures[0].error;
  EXPECT_EQ(failures[1].name, "win.obj");
  EXPECT_EQ(failures[1].count, 100U);
  EXPECT_EQ(failures[1].error,
            "asset 'win.obj' not found (looked in " + (dir / "rules" / "win.obj").string() + ", " +
                (dir / "assets" / "win.obj").string() + ", " + (dir / "win.obj").string() + ")");
}

TEST(AssetLibrary, MissingIsAnErrorWhenAsked) {
  const TempFolder dir;
  const AssetLibrary library(
      [](std::string_view name, std::string& error) -> std::optional<std::filesystem::path> {
        error = "no '" + std::string(name) + "' here";
        return std::nullopt;
      },
      AssetLibrary::Missing::kError);
  std::string error;
  EXPECT_EQ(library.find("door", error), nullptr);
  EXPECT_EQ(error, "no 'door' here");
  EXPECT_EQ(library.failures().size(), 1U);
}

}  // namespace
}  // namespace insula::io
