// SPDX-License-Identifier: LGPL-2.1-or-later
#include "cli/commands.hpp"

namespace sliceform::cli {

void addModelOptions(CLI::App* command, ModelOptions& options) {
  command->add_option("model", options.model, "STEP, IGES, BREP, STL, OBJ or OFF file")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_flag("--fill-holes", options.fillHoles,
                    "fill every hole of a mesh whose rim is a simple loop (by default only those up to " +
                        std::to_string(static_cast<int>(kMaxFilledHoleSpan * 100)) +
                        " % of the model's size across), with a fan of triangles about its centre");
  addParameter(command, "u", options.u)->delimiter(',')->expected(3);
  addParameter(command, "v", options.v)->delimiter(',')->expected(3);
}

}  // namespace sliceform::cli
