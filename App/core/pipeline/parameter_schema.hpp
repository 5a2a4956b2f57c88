// SPDX-License-Identifier: LGPL-2.1-or-later
// The design's parameters, described once: name, kind, default, range, unit, group and the
// one-line help. The CLI takes its option help from here, the binding hands the table to
// FreeCAD, which makes its properties (types, groups, tooltips, defaults), the task panel's
// rows and checks its preferences page against it. Defaults of parameters the core's structs
// hold are read from those structs (DesignParams{}), so they are stated once.
#pragma once

#include <string>
#include <vector>

namespace sliceform {

enum class ParamKind {
  Real,       // a number; unit "mm", "s", "deg" or none
  Integer,    // a count
  Bool,       // on or off
  Choice,     // one of `choices`; the default is the first
  Direction,  // x,y,z
};

struct ParamSpec {
  std::string key;       // the binding's dict key and report.json's parameter name
  std::string option;    // the CLI option ("--min-hinge-length"), "" when the CLI has none
  std::string property;  // the FreeCAD property ("MinHingeLength"), "" when FreeCAD has none
  std::string group;     // Slicing, Hinges, Material, Sheets, Assembly
  ParamKind kind = ParamKind::Real;
  std::string unit;                  // "mm", "s", "deg" or ""
  double value = 0;                  // the default of a Real, Integer or Bool (0/1)
  std::vector<double> direction;     // the default of a Direction
  std::vector<std::string> choices;  // a Choice's values, the default first
  double min = 0, max = 0;           // the range the core accepts (Real, Integer)
  double step = 1;                   // a spin box's step (Real, Integer)
  std::string label;                 // a short name for a form row ("Shortest hinge")
  std::string help;                  // one line: what it does, as the CLI and a tooltip say it
};

// Every design parameter, in the order forms show them.
const std::vector<ParamSpec>& designParameterSchema();
// The one with this key; throws std::out_of_range for an unknown key.
const ParamSpec& parameterSpec(const std::string& key);

}  // namespace sliceform
