// SPDX-License-Identifier: LGPL-2.1-or-later
#include "cli/commands.hpp"

namespace sliceform::cli {

void addModelOptions(CLI::App* command, ModelOptions& options) {
  command->add_option("model", options.model, "STEP, IGES, BREP, STL, OBJ or OFF file")
      ->required()
      ->check(CLI::ExistingFile);
  const ParamSpec& fill = parameterSpec("fill_holes");
  command->add_flag(fill.option, options.fillHoles, fill.help);
  addParameter(command, "u", options.u)->delimiter(',')->expected(3);
  addParameter(command, "v", options.v)->delimiter(',')->expected(3);
}

}  // namespace sliceform::cli
