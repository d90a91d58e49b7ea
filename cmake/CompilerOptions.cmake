# SPDX-License-Identifier: MIT
# Warnings for lookahead's own targets only (third-party headers are included as SYSTEM).
function(lookahead_compile_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
  if(CMAKE_BUILD_TYPE STREQUAL "Release")
    # -O3 for the hot loops (ray casting, likelihoods, scan matching); no -march=native so a
    # binary built on one machine runs on another of the same kind.
    target_compile_options(${target} PRIVATE -O3)
  endif()
endfunction()
