// SPDX-License-Identifier: LGPL-2.1-or-later
// libFuzzer target of one mesh reader: the input bytes become a model file with the
// extension SLICEFORM_FUZZ_EXTENSION (set per executable), read by readModel as the CLI
// reads it, then checked as the arrangement checks every model (requireClosed,
// requireOneSolid). A sliceform::Error is how a bad file is meant to be refused; anything
// else (a crash, a sanitizer report, an exception of another type escaping) is a finding.
#include <Message.hxx>
#include <Message_Messenger.hxx>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

#include "model/model.hpp"
#include "support/error.hpp"

namespace {

// The readers take a path: one file per process (parallel jobs do not share it),
// rewritten for every input.
std::string path;

void removeInput() {
  std::remove(path.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* dir = std::getenv("TMPDIR");
  path = std::string(dir && *dir ? dir : "/tmp") + "/sliceform-fuzz-" + std::to_string(getpid()) +
         SLICEFORM_FUZZ_EXTENSION;
  std::atexit(removeInput);
  // OCCT's readers complain about bad files on stdout; printing that for every input
  // would cost more than the reading.
  Message::DefaultMessenger()->ChangePrinters().Clear();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) std::abort();  // no place for the input: nothing below would be tested
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  try {
    const sliceform::Model model = sliceform::readModel(path);
    sliceform::requireClosed(model);
    sliceform::requireOneSolid(model);
  } catch (const sliceform::Error&) {
  }
  return 0;
}
