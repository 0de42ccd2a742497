// io::OutputTransaction (issue 12, item 1): cancelled at every step it asks, a transaction leaves
// either all the user's earlier files or all the new ones, never a backup, a temporary or a mix.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/output.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

namespace fs = std::filesystem;

std::string content(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// out.glb, out.obj, out.mtl and report.json with "old <name>" in each.
void write_old_files(const fs::path& dir) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const char* name : {"out.glb", "out.obj", "out.mtl", "out.origin.json", "report.json"}) {
    std::ofstream(dir / name) << "old " << name;
  }
}

std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The transaction a command runs: two scenes, the report, the commit. False when a step failed.
bool run(const fs::path& dir, OutputTransaction& transaction) {
  const shape::Scene scene = testing::test_scene();
  return transaction.write_scene(scene, (dir / "out.glb").string()).empty() &&
         transaction.write_scene(scene, (dir / "out.obj").string()).empty() &&
         transaction.write_text((dir / "report.json").string(), "{}\n").empty() &&
         transaction.commit().empty();
}

TEST(OutputTransaction, CancelledAtAnyStepKeepsAllOldFilesElseAllNew) {
  const fs::path dir = testing::temp_dir("transaction");
  const std::vector<std::string> names = {"out.glb", "out.mtl", "out.obj", "out.origin.json",
                                          "report.json"};
  int committed = 0;
  for (int allowed = 0; allowed < 20; ++allowed) {
    write_old_files(dir);
    int asked = 0;
    bool ok = false;
    {
      OutputTransaction transaction([&] { return asked++ >= allowed; });
      ok = run(dir, transaction);
    }  // an unfinished transaction rolls back here
    EXPECT_EQ(listing(dir), names) << "cancelled after " << allowed << " questions";
    for (const std::string& name : names) {
      if (ok) {
        EXPECT_NE(content(dir / name), "old " + name) << name << ", committed";
      } else {
        EXPECT_EQ(content(dir / name), "old " + name) << name << ", cancelled at " << allowed;
      }
    }
    committed += ok ? 1 : 0;
  }
  EXPECT_GT(committed, 0);  // the last runs got through
  EXPECT_LT(committed, 20);
  fs::remove_all(dir);
}

TEST(OutputTransaction, FailedWriteRestoresAndRemovesTheNewFiles) {
  const fs::path dir = testing::temp_dir("transaction_fail");
  write_old_files(dir);
  {
    OutputTransaction transaction;
    const shape::Scene scene = testing::test_scene();
    EXPECT_TRUE(transaction.write_scene(scene, (dir / "out.glb").string()).empty());
    EXPECT_FALSE(
        transaction.write_scene(scene, (dir / "missing" / "x.city.json").string()).empty());
  }
  EXPECT_EQ(content(dir / "out.glb"), "old out.glb");
  EXPECT_FALSE(fs::exists(dir / "out.glb.insula-backup"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace insula::io
