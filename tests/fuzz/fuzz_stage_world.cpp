// SPDX-License-Identifier: MIT
// Stage .world reader: syntax, define chains, floorplan lookup (its bitmap is usually not
// found, which ends the load with a ParseError after parsing).
#include <exception>

#include "fuzz_input.hpp"
#include "lookahead/exploration/world_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const lookahead::fuzz::InputFile file(data, size, ".world");
  try {
    (void)lookahead::exploration::load_stage_world(file.path());
  } catch (const std::exception&) {
  }
  return 0;
}
