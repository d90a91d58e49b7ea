// SPDX-License-Identifier: MIT
// map_server YAML + image loaders (slam::read_map and exploration::load_map_yaml). The input
// is the YAML, a line "---image---", then the image bytes; the YAML's `image:` is replaced by
// the image file's path so every input reaches the image decoder.
#include <exception>
#include <string>

#include "fuzz_input.hpp"
#include "lookahead/exploration/world_loader.hpp"
#include "lookahead/slam/io/map_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string separator = "\n---image---\n";
  const std::size_t cut = text.find(separator);
  const std::string yaml = text.substr(0, cut);
  const std::string image = cut == std::string::npos ? "" : text.substr(cut + separator.size());
  const lookahead::fuzz::InputFile image_file(reinterpret_cast<const std::uint8_t*>(image.data()), image.size(),
                                              ".pgm");
  const std::string with_path = "image: " + image_file.path() + "\n" + yaml;
  const lookahead::fuzz::InputFile yaml_file(reinterpret_cast<const std::uint8_t*>(with_path.data()), with_path.size(),
                                             ".yaml");
  try {
    (void)lookahead::slam::read_map(yaml_file.path());
  } catch (const std::exception&) {
  }
  try {
    (void)lookahead::exploration::load_map_yaml(yaml_file.path());
  } catch (const std::exception&) {
  }
  return 0;
}
