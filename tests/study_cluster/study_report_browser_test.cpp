// SPDX-License-Identifier: MIT
// report.html of a small study opened from the file system in headless Chromium (Debian's
// chromium): no console messages, its tables and every run's map thumbnail in the document,
// every picture loaded (a checker page beside it frames the report and reports each image's
// natural size), and a screenshot in the test output folder. With one map removed the
// checker must name it, so the check can fail.
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
      "--no-first-run --disable-dev-shm-usage --disable-background-networking "
      "--disable-component-update "
      "--disable-sync --enable-logging=stderr --v=0 --allow-file-access-from-files "
      "--virtual-time-budget=10000 --window-size=1280,2400 --user-data-dir=" +
      profile.string() + " " + action + " file://" + page.string());
}

// Lines of Chromium's log that carry a page's console messages or script errors.
std::vector<std::string> console_errors(const std::string& log) {
  std::vector<std::string> errors;
  std::stringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(":CONSOLE") != std::string::npos || line.find("Uncaught") != std::string::npos)
      errors.push_back(line);
  }
  return errors;
}

// A page that frames out/report.html and writes "images N broken K <srcs>" once the
// report's pictures had the time to load.
constexpr const char* kChecker = R"(<!DOCTYPE html><html><body><pre id="result">pending</pre>
<iframe id="f" src="out/report.html" width="1200" height="800"></iframe>
<script>
document.getElementById('f').addEventListener('load', () => {
  const images = Array.from(document.getElementById('f').contentDocument.images);
  images.forEach(i => { i.loading = 'eager'; });
  setTimeout(() => {
    const broken = images.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src'));
    document.getElementById('result').textContent =
        'images ' + images.length + ' broken ' + broken.length + ' ' + broken.join(' ');
  }, 2000);
});
</script></body></html>
)";

std::string image_check(const std::string& dom) {
  std::smatch m;
  return std::regex_search(dom, m, std::regex("images [0-9]+ broken [0-9]+[^<]*")) ? m.str() : "";
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(StudyReport, OpensInHeadlessChromiumWithEveryTableAndMap) {
  if (shell("command -v chromium").code != 0) GTEST_SKIP() << "chromium is not installed (scripts/install_deps.sh)";
  const TempDir tmp("lookahead-study-report");
  std::ofstream(tmp.path / "s.yaml") << tiny_study("report", tmp.path / "out", 2, 5);
  Shell r = shell(kBin + " study " + (tmp.path / "s.yaml").string() + " --jobs 2");
  ASSERT_EQ(r.code, 0) << r.output;
  const fs::path page = tmp.path / "out/report.html";

  r = chromium(tmp.path / "profile", page, "--dump-dom");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(console_errors(r.output).empty()) << r.output;
  EXPECT_NE(r.output.find(" of 8 missions reached the coverage goal"), std::string::npos) << r.output;
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

  const fs::path checker = tmp.path / "check.html";
  std::ofstream(checker) << kChecker;
  r = chromium(tmp.path / "profile", checker, "--dump-dom");
  EXPECT_EQ(image_check(r.output), "images 11 broken 0 ") << r.output;  // 8 maps, 3 plots
  EXPECT_TRUE(console_errors(r.output).empty()) << r.output;

  fs::remove(tmp.path / "out/runs/maze__utility__2/map.png");  // the check must see this
  r = chromium(tmp.path / "profile", checker, "--dump-dom");
  EXPECT_EQ(image_check(r.output), "images 11 broken 1 runs/maze__utility__2/map.png") << r.output;
}

}  // namespace
}  // namespace lookahead::test
