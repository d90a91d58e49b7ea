// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/run_json.hpp"

#include <filesystem>
#include <fstream>

#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/io/provenance_json.hpp"

namespace lookahead::slam {

void write_run_json(const std::string& dir, nlohmann::json figures, int threads,
                    const std::string& configuration_yaml) {
  figures["provenance"] = to_json(provenance(threads));
  figures["configuration_yaml"] = configuration_yaml;
  const std::filesystem::path path = std::filesystem::path(dir) / "run.json";
  const std::filesystem::path part = std::filesystem::path(dir) / "run.json.part";
  {
    std::ofstream out(part);
    out << figures.dump(2) << "\n";
    if (!out) throw ParseError(part.string(), 0, "", "", "cannot write");
  }
  std::filesystem::rename(part, path);
}

}  // namespace lookahead::slam
