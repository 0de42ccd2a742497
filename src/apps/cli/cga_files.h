// CGA's file functions (fileExists, fileSearch, fileRandom, assetInfo, imageInfo, readStringTable,
// readFloatTable) answered by io::FileFunctions, the asset search the grammar's inserts use
// (docs/assets.md).
#pragma once

#include "io/file_functions.h"
#include "lang/cga/derive.h"

namespace insula::cli {

class CgaFiles final : public lang::cga::FileQueries {
 public:
  explicit CgaFiles(const io::FileFunctions& files) : files_(files) {}

  bool exists(const std::string& path) const override { return files_.file_exists(path); }
  std::string search(const std::string& query, std::string& error) const override {
    return files_.file_search(query, error);
  }
  std::string random(const std::string& query, double random, std::string& error) const override {
    return files_.file_random(query, random, error);
  }
  std::optional<double> asset_info(const std::string& path, const std::string& what,
                                   std::string& error) const override {
    return files_.asset_info(path, what, error);
  }
  std::optional<double> image_info(const std::string& path, const std::string& what,
                                   std::string& error) const override {
    return files_.image_info(path, what, error);
  }
  std::optional<std::string> read_text(const std::string& path, std::string& error) const override {
    return files_.read_text(path, error);
  }

 private:
  const io::FileFunctions& files_;
};

}  // namespace insula::cli
