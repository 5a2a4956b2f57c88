// SPDX-License-Identifier: LGPL-2.1-or-later
// The sub-commands of the `sliceform` program. Each adds itself to the CLI11 app and
// returns the callback main() runs when it is chosen.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "frames/hinge_table.hpp"
#include "frames/stabilize.hpp"
#include "geometry/vec.hpp"
#include "pipeline/parameter_schema.hpp"
#include "realization/slots.hpp"

namespace sliceform::cli {

using Run = std::function<void()>;

// What every command asks first: the model file and the two slicing directions.
struct ModelOptions {
  std::string model;
  bool fillHoles = false;  // every hole of a mesh, not only the small ones
  std::vector<double> u = parameterSpec("u").direction, v = parameterSpec("v").direction;

  Vec3 uDirection() const { return {u[0], u[1], u[2]}; }
  Vec3 vDirection() const { return {v[0], v[1], v[2]}; }
};

void addModelOptions(CLI::App* command, ModelOptions& options);

Run addSliceCommand(CLI::App& app);
Run addDesignCommand(CLI::App& app);
Run addCouponCommand(CLI::App& app);

// An option of the parameter schema: its name, help and (Choice) values from there, the
// field's value shown as the default. `names` replaces the option's name ("-n,--slices").
template <class T>
CLI::Option* addParameter(CLI::App* command, const std::string& key, T& field,
                          const std::string& names = "") {
  const ParamSpec& s = parameterSpec(key);
  CLI::Option* option = command->add_option(names.empty() ? s.option : names, field, s.help);
  if (s.kind == ParamKind::Choice && key != "sheet") option->check(CLI::IsMember(s.choices));
  return option->capture_default_str();
}

// The material and slot rules, one definition for `design` and `coupon`.
void addSlotOptions(CLI::App* command, SlotParams& slots, HingeRules& rules, StabilizeOptions& spacing);

}  // namespace sliceform::cli
