# SPDX-License-Identifier: LGPL-2.1-or-later
# The instrumented build that scripts/sanitize and scripts/fuzz share (build-sanitize): clang,
# AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer's coverage on every target of
# ours, the core's GoogleTest suite and the fuzz targets in one tree. One build for both, and
# clang's: a fresh clone (CI) compiled the core instrumented twice, once with gcc, whose
# sanitized compile took ~3x clang's (realization/realize.cpp: 57 s against 20 s).
# Usage (from the repository root): sanitized_build TARGET...
sanitized_build() {
  cmake -S . -B build-sanitize -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSLICEFORM_FUZZ=ON -DSLICEFORM_BUILD_PYTHON=OFF -DSLICEFORM_BUILD_TESTS=ON >/dev/null
  cmake --build build-sanitize --target "$@" -j"${JOBS:-$(nproc)}"
}
