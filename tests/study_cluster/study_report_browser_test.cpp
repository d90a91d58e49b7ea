// SPDX-License-Identifier: MIT
// report.html of a small study opened from the file system in headless Chromium (Debian's
// chromium): no console errors (a missing picture logs "Failed to load resource"), its
// tables and every run's map thumbnail in the document, and a screenshot in the test output
// folder. A copy with one picture removed must show the error, so the check can fail.
#include <regex>

#include "cluster_test_support.hpp"

namespace lookahead::test {
namespace {

const std::string kBin = LOOKAHEAD_BINARY;

// Headless Chromium on `page` with a fresh profile and no network services; `action` is
// --dump-dom or --screenshot=PATH. Returns its output (DOM on stdout, console on stderr).
Shell chromium(const fs::path& profile, const fs::path& page, const std::string& action) {
  fs::remove_all(profile);
  fs::create_directories(profile);
  return shell(
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic "
      "--no-first-run --disable-background-networking --disable-component-update "
      "--disable-sync --enable-logging=stderr --v=0 --allow-file-access-from-files "
      "--window-size=1280,2400 --user-data-dir=" +
      profile.string() + " " + action + " file://" + page.string());
}

std::vector<std::string> console_errors(const std::string& log) {
  std::vector<std::string> errors;
  std::stringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    if (line.find("CONSOLE") != std::string::npos ||
        line.find("Failed to load") != std::string::npos ||
        line.find("Uncaught") != std::string::npos)
      errors.push_back(line);
  }
  return errors;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(StudyReport, OpensInHeadlessChromiumWithEveryTableAndMap) {
  if (shell("command -v chromium").code != 0)
    GTEST_SKIP() << "chromium is not installed (scripts/install_deps.sh)";
  const TempDir tmp("lookahead-study-report");
  std::ofstream(tmp.path / "s.yaml") << tiny_study("report", tmp.path / "out", 2, 5);
  Shell r = shell(kBin + " study " + (tmp.path / "s.yaml").string() + " --jobs 2");
  ASSERT_EQ(r.code, 0) << r.output;
  const fs::path page = tmp.path / "out/report.html";

  r = chromium(tmp.path / "profile", page, "--dump-dom");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(console_errors(r.output).empty()) << r.output;
  EXPECT_NE(r.output.find(" of 8 missions reached the coverage goal"), std::string::npos)
      << r.output;
  EXPECT_EQ(count(r.output, "<table class=\"strategies\">"), 2u);  // maze, corridor
  EXPECT_EQ(count(r.output, "<table class=\"paired\">"), 2u);
  EXPECT_EQ(count(r.output, "class=\"run-map\""), 8u);
  EXPECT_NE(r.output.find("src=\"coverage_maze.png\""), std::string::npos);

  const fs::path shots = fs::path(LOOKAHEAD_TEST_OUTPUT_DIR);
  fs::create_directories(shots);
  fs::remove(shots / "study_report.png");
  r = chromium(tmp.path / "profile", page, "--screenshot=" + (shots / "study_report.png").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(console_errors(r.output).empty()) << r.output;
  ASSERT_TRUE(fs::exists(shots / "study_report.png"));
  EXPECT_GT(fs::file_size(shots / "study_report.png"), 20000u);

  fs::remove(tmp.path / "out/runs/maze__utility__2/map.png");  // the check must see this
  r = chromium(tmp.path / "profile", page, "--dump-dom");
  EXPECT_FALSE(console_errors(r.output).empty()) << r.output;
}

}  // namespace
}  // namespace lookahead::test
