// SPDX-License-Identifier: LGPL-2.1-or-later
#include "cli/commands.hpp"

namespace sliceform::cli {

void addModelOptions(CLI::App* command, ModelOptions& options) {
  command->add_option("model", options.model, "STEP, IGES, BREP, STL, OBJ or OFF file")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--u", options.u, "U slicing direction x,y,z")
      ->delimiter(',')
      ->expected(3)
      ->capture_default_str();
  command->add_option("--v", options.v, "V slicing direction x,y,z (W = U x V is up)")
      ->delimiter(',')
      ->expected(3)
      ->capture_default_str();
}

}  // namespace sliceform::cli
