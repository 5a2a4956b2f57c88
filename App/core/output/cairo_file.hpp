// SPDX-License-Identifier: LGPL-2.1-or-later
// The steps every cairo file writer shares: a surface's status checked as an Io error, and a
// surface drawn on and finished before writeAtomically renames the file.
#pragma once

#include <cairo.h>

#include <string>

#include "support/error.hpp"

namespace sliceform {

inline void checkSurface(cairo_surface_t* surface, const std::string& path) {
  const cairo_status_t status = cairo_surface_status(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw Error(ErrorKind::Io, "cannot write " + path + ": " + cairo_status_to_string(status));
}

// Runs `draw` on a context of `surface`, then finishes and releases the surface; throws Io
// when cairo reports a failure.
template <class Draw>
void drawAndFinish(cairo_surface_t* surface, const std::string& path, Draw draw) {
  cairo_t* cr = cairo_create(surface);
  draw(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw Error(ErrorKind::Io, "cannot write " + path + ": " + cairo_status_to_string(status));
}

}  // namespace sliceform
