// SPDX-License-Identifier: LGPL-2.1-or-later
// The sub-commands of the `sliceform` program. Each adds itself to the CLI11 app and
// returns the callback main() runs when it is chosen.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace sliceform::cli {

using Run = std::function<void()>;

Run addSliceCommand(CLI::App& app);
Run addDesignCommand(CLI::App& app);

}  // namespace sliceform::cli
