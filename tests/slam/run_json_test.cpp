// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/run_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

namespace fs = std::filesystem;

// The figures, the provenance block and the configuration land in DIR/run.json, and no
// partial file is left beside it.
TEST(RunJson, WritesFiguresProvenanceAndConfiguration) {
  const fs::path dir = fs::temp_directory_path() / "lookahead-run-json-test";
  fs::create_directories(dir);
  write_run_json(dir.string(), {{"coverage", 0.95}}, 2, "mission:\n  seed: 3\n");
  std::ifstream in(dir / "run.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_DOUBLE_EQ(j["coverage"].get<double>(), 0.95);
  EXPECT_EQ(j["provenance"]["threads"].get<int>(), 2);
  EXPECT_FALSE(j["provenance"]["commit"].get<std::string>().empty());
  EXPECT_EQ(j["configuration_yaml"].get<std::string>(), "mission:\n  seed: 3\n");
  EXPECT_FALSE(fs::exists(dir / "run.json.part"));
  fs::remove_all(dir);
}

// A folder that cannot be written to is an error that names the file.
TEST(RunJson, UnwritableFolderNamesTheFile) {
  try {
    write_run_json("/nonexistent-lookahead-folder", {{"a", 1}}, 1, "");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-lookahead-folder/run.json.part"), std::string::npos);
  }
}

}  // namespace
}  // namespace lookahead::slam
