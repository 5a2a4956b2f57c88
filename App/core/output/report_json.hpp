// SPDX-License-Identifier: LGPL-2.1-or-later
// report.json: the design in a documented form other tools can check it with
// (docs/report-format.md; ../shared/tools/check_report.py reads it). Patches carry their
// plane and slotted outline, hinges their 3D ends and slot types; then the certificate, the
// interlock results, the measured slot-to-edge distance and hinge length, quality and the
// assembly order. Nothing in it depends on timing, so the same input gives the same bytes;
// timings go to timings.json.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "pipeline/design.hpp"

namespace sliceform {

// `design` laid out (runDesign, or layOutDesign after designPatches); std::invalid_argument
// if it is not.
nlohmann::json reportJson(const Model& model, const DesignParams& params, const Design& design);
nlohmann::json timingsJson(const std::vector<StageTime>& timings);
void writeJson(const nlohmann::json& doc, const std::string& path);

}  // namespace sliceform
