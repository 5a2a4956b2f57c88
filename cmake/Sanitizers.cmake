# SPDX-License-Identifier: LGPL-2.1-or-later
# Sanitizer and fuzzing builds (issue 8). Both instrument every target of this build;
# OCCT and the other system libraries stay uninstrumented.
option(SLICEFORM_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(SLICEFORM_FUZZ "Build the libFuzzer targets of tests/fuzz (clang; implies the sanitizers)" OFF)

if(SLICEFORM_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SLICEFORM_FUZZ needs clang: configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  # Coverage feedback for libFuzzer in our code; the fuzz targets add -fsanitize=fuzzer
  # (libFuzzer's main) when they link.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(SLICEFORM_SANITIZE OR SLICEFORM_FUZZ)
  # No recovery: a UBSan report aborts, so tests and the fuzzer see it as a failure
  # rather than a line in a log. Frame pointers keep ASan's stack traces whole. Line tables
  # are all a report's file:line needs (after the build type's -g, so they win): objects
  # half the size, ~10 % less compile time (clang, realization/realize.cpp).
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    set(SLICEFORM_LINE_TABLES -gline-tables-only)
  else()
    set(SLICEFORM_LINE_TABLES -g1)
  endif()
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer ${SLICEFORM_LINE_TABLES})
  add_link_options(-fsanitize=address,undefined)
endif()
