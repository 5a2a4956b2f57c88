// SPDX-License-Identifier: LGPL-2.1-or-later
// The arranged scaffold as JSON: every patch with its family, plane (origin, normal,
// in-plane axes, mm) and outline loops in plane coordinates, every hinge with its two
// patches and its 3D segment, the certificate and the quality. Keys follow report.json
// (issue 5), so ../shared/tools/check_report.py can check a scaffold already.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "arrangement/arrange.hpp"

namespace sliceform {

nlohmann::json scaffoldJson(const Arrangement& a, const ArrangementParams& params);
void writeJson(const nlohmann::json& doc, const std::string& path);

}  // namespace sliceform
