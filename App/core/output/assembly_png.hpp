// SPDX-License-Identifier: LGPL-2.1-or-later
// A picture of the assembled sliceform, drawn in software (no OpenGL, no display) so the
// CLI and the tests can make it anywhere: an orthographic view from the front right and a
// little above, panels z-buffered and shaded two-sided in two paper colours, with dark edges
// so the slotted lattice reads clearly. Written as PNG with libpng (png_file.hpp).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "arrangement/arrange.hpp"
#include "exact/patch_faces.hpp"
#include "geometry/vec.hpp"

namespace sliceform {

// One patch in 3D at the fold pose.
struct Panel3 {
  std::vector<std::vector<Vec3>> loops;  // outer loops and holes (even-odd), mm
  Vec3 normal;                           // the patch plane's normal; panels are two-sided
  int family = 0;                        // 0 = U, 1 = V: two paper colours
  int patch = -1;                        // the design's patch index
};

// The patches' outlines at fold angle theta (degrees, in (0, 90]), at the same poses as
// assemble(); patches without an outline are left out.
std::vector<Panel3> assemblyPanels(const Arrangement& a, const std::vector<PatchFace>& patches,
                                   double thetaDegrees);

// The drawn picture, before it is a PNG: 0x00RRGGBB per pixel, row by row.
struct Picture {
  int width = 0, height = 0;
  std::vector<uint32_t> pixels;
};

// The view's up is W, found as (U normal) x (V normal) from the panels (+z if the panels
// are all of one family); the picture is widthPixels wide and as high as the model needs
// (at most 1.5 times the width). Throws BadParameter. Uses no cairo: it may run beside
// the sheets' cairo surfaces without changing their ids (see design_files.cpp).
Picture drawAssembly(const std::vector<Panel3>& panels, int widthPixels = 1200);

// Pictures of a growing assembly, at the place and scale the whole one has, so they line
// up: add(k) adds panel k (an index into `panels`) to those shown and draws them with it
// in the highlight colour (kHighlight), x-rayed where other paper hides it. Each panel is
// filled once into a kept depth buffer, and the picture before the step is kept: a step
// draws again only the new panel's box (a copy of it, the panel highlighted, the edges).
// The assembly instructions' step pictures.
class GrowingAssembly {
 public:
  GrowingAssembly(const std::vector<Panel3>& panels, int widthPixels);
  ~GrowingAssembly();
  // The picture with `panel` added; valid until the next add (one picture is kept and
  // changed in the boxes of this step and the one before).
  const Picture& add(int panel);

 private:
  struct State;
  std::unique_ptr<State> state_;
};
// The colour of the patch a step adds, RGB 0..255: a warm orange no paper colour comes near.
constexpr uint32_t kHighlight = 0xE8603C;

// Written atomically (writeRgbPng). Throws Io.
void writePicturePng(const Picture& picture, const std::string& path);

// drawAssembly, then writePicturePng.
void writeAssemblyPng(const std::vector<Panel3>& panels, const std::string& path, int widthPixels = 1200);

// The paper colour of a family (0 = U, 1 = V), RGB in [0, 1]; the glTF uses the same two.
struct PaperColour {
  double r, g, b;
};
PaperColour paperColour(int family);

}  // namespace sliceform
