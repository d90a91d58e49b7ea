// SPDX-License-Identifier: MIT
// MRPT rawlog reader through its guard (a child process with memory and CPU limits).
#include <exception>

#include "fuzz_input.hpp"
#include "lookahead/slam/io/laser_log.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const lookahead::fuzz::InputFile file(data, size, ".rawlog");
  try {
    (void)lookahead::slam::read_mrpt_rawlog(file.path());
  } catch (const std::exception&) {
  }
  return 0;
}
