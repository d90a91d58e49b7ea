# SPDX-License-Identifier: MIT
# Separate configurations (own build folders; the default GCC build is unchanged):
#   LOOKAHEAD_SANITIZE  ASan + UBSan on every target (scripts/sanitize.sh, build-sanitize/)
#   LOOKAHEAD_FUZZ      the libFuzzer harnesses of tests/fuzz, with ASan + UBSan; needs clang
#                       (scripts/fuzz.sh, build-fuzz/)
#   LOOKAHEAD_FUZZ_SANITIZERS  the sanitizers of a fuzz build: "undefined" for the rawlog
#                       reader's guard, whose child limits its address space (ASan's shadow
#                       reservation rules that out, and under ASan a corrupt size claim kills
#                       the child instead of failing the allocation; build-fuzz-guard/)
option(LOOKAHEAD_SANITIZE "Build everything with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(LOOKAHEAD_FUZZ "Build the libFuzzer harnesses (clang only), sanitized" OFF)
set(LOOKAHEAD_FUZZ_SANITIZERS "address,undefined" CACHE STRING "sanitizers of the fuzz build")
set(_sanitizers address,undefined)
if(LOOKAHEAD_FUZZ)
  set(_sanitizers ${LOOKAHEAD_FUZZ_SANITIZERS})
endif()
if(LOOKAHEAD_SANITIZE OR LOOKAHEAD_FUZZ)
  # UBSan findings stop the run, so a test or fuzzer fails on them instead of printing.
  add_compile_options(-fsanitize=${_sanitizers} -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=${_sanitizers})
endif()
if(LOOKAHEAD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "LOOKAHEAD_FUZZ needs clang: cmake -DCMAKE_CXX_COMPILER=clang++ ...")
  endif()
  # Coverage instrumentation for every library the harnesses reach; -fsanitize=fuzzer
  # (the libFuzzer main) is linked into the harnesses only.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
