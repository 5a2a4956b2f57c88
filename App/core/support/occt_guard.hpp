// SPDX-License-Identifier: LGPL-2.1-or-later
// Runs an OCCT call and turns Standard_Failure (OCCT's exception root) into our Error,
// so no OCCT exception type ever crosses the core's interface.
#pragma once

#include <Standard_Failure.hxx>

#include <string>
#include <utility>

#include "support/error.hpp"

namespace sliceform {

template <class Fn>
auto occtGuard(const char* what, Fn&& fn) -> decltype(fn()) {
  try {
    return std::forward<Fn>(fn)();
  } catch (const Standard_Failure& failure) {
    std::string detail = failure.GetMessageString() ? failure.GetMessageString() : "";
    throw Error(ErrorKind::Geometry, std::string(what) + " failed in OpenCASCADE (" +
                                         failure.DynamicType()->Name() +
                                         (detail.empty() ? "" : ": " + detail) + ")");
  }
}

}  // namespace sliceform
