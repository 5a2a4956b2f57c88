// SPDX-License-Identifier: LGPL-2.1-or-later
// Outputs are written under a temporary name in the target folder and renamed into place,
// so a failed or interrupted run never leaves a half-written file over a good one.
#pragma once

#include <functional>
#include <string>

namespace sliceform {

// Calls write(temporaryPath), then renames the temporary file to `path`. If write throws or
// the rename fails, the temporary file is removed and `path` is left as it was.
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace sliceform
