// SPDX-License-Identifier: MIT
#include "run_json.hpp"

#include <filesystem>
#include <fstream>

#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/io/provenance_json.hpp"

namespace lookahead::app {

void write_run_json(const std::string& dir, nlohmann::json figures, int threads,
                    const std::string& configuration_yaml) {
  figures["provenance"] = slam::to_json(slam::provenance(threads));
  figures["configuration_yaml"] = configuration_yaml;
  const std::filesystem::path path = std::filesystem::path(dir) / "run.json";
  const std::filesystem::path part = std::filesystem::path(dir) / "run.json.part";
  {
    std::ofstream out(part);
    out << figures.dump(2) << "\n";
    if (!out) throw slam::ParseError(part.string(), 0, "", "", "cannot write");
  }
  std::filesystem::rename(part, path);
}

std::string indent(const std::string& yaml) {
  std::string out;
  std::size_t start = 0;
  while (start < yaml.size()) {
    const std::size_t end = yaml.find('\n', start);
    const std::size_t stop = end == std::string::npos ? yaml.size() : end + 1;
    out += "  " + yaml.substr(start, stop - start);
    start = stop;
  }
  return out;
}

}  // namespace lookahead::app
