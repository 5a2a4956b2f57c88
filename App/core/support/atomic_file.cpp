// SPDX-License-Identifier: LGPL-2.1-or-later
#include "support/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "support/error.hpp"

namespace sliceform {

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  // Same folder as the target, so the rename stays on one file system and is atomic.
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  try {
    write(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw Error(ErrorKind::Io, "cannot write " + path + ": " + ec.message());
  }
}

}  // namespace sliceform
