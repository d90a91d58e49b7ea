// SPDX-License-Identifier: MIT
// CARMEN log reader: any bytes either read or end in an exception (ParseError for bad lines).
#include <exception>

#include "fuzz_input.hpp"
#include "lookahead/slam/io/laser_log.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const lookahead::fuzz::InputFile file(data, size, ".log");
  for (const bool skip : {false, true}) {
    lookahead::slam::LogReadOptions options;
    options.skip_bad_lines = skip;
    try {
      (void)lookahead::slam::read_carmen_log(file.path(), options);
    } catch (const std::exception&) {
    }
  }
  return 0;
}
