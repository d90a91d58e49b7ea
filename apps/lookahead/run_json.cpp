// SPDX-License-Identifier: MIT
#include "run_json.hpp"

namespace lookahead::app {

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
