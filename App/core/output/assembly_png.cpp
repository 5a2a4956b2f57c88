// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/assembly_png.hpp"

#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "assembly/fold.hpp"
#include "output/png_file.hpp"
#include "support/atomic_file.hpp"
#include "support/error.hpp"
#include "support/parallel.hpp"
#include "support/per_family.hpp"

namespace sliceform {
namespace {

// From the front right and a little above, like an isometric view but less steep, so the
// slots along W stay visible.
constexpr double kAzimuth = 35 * M_PI / 180;    // from the front (-V) towards the right (+U)
constexpr double kElevation = 25 * M_PI / 180;  // above the U-V plane
constexpr int kSupersample = 2;                 // drawn 2x2 larger, then averaged: cheap anti-aliasing
constexpr double kMargin = 0.04;                // of the width, on every side
constexpr double kMaxAspect = 1.5;              // height / width at most
constexpr double kFade = 0.3;                   // how much paler the farthest paper is: depth cue
constexpr uint32_t kEdge = 0x383838;            // grey of the edge lines (0.22)
constexpr uint32_t kWhite = 0xFFFFFF;

// 0x00RRGGBB from channels in [0, 1].
uint32_t packed(float r, float g, float b) {
  // Rounded half up (not std::lround, a library call per channel and pixel).
  const auto c = [](float v) {
    return v == v ? static_cast<uint32_t>(std::clamp(v, 0.0f, 1.0f) * 255 + 0.5f) : 0u;
  };
  return c(r) << 16 | c(g) << 8 | c(b);
}

// Each channel halfway between two colours.
uint32_t halfway(uint32_t a, uint32_t b) {
  uint32_t out = 0;
  for (int shift = 0; shift <= 16; shift += 8)
    out |= ((((a >> shift) & 255) + ((b >> shift) & 255) + 1) / 2) << shift;
  return out;
}

// Screen axes and the direction towards the viewer, orthonormal, in model coordinates.
struct View {
  Vec3 right, up, toViewer;
};

// W = U x V from a U panel and a V panel. A V-patch folded by theta has normal
// cos(90° - theta) V - sin(90° - theta) U, so U x that is still along +W.
Vec3 modelUp(const std::vector<Panel3>& panels) {
  const Panel3* u = nullptr;
  const Panel3* v = nullptr;
  for (const Panel3& p : panels) {
    if (p.family == 0 && !u) u = &p;
    if (p.family != 0 && !v) v = &p;
  }
  if (u && v) {
    const Vec3 w = cross(u->normal, v->normal);
    if (norm(w) > 1e-6) return normalized(w);
  }
  return {0, 0, 1};
}

View makeView(const std::vector<Panel3>& panels) {
  const Vec3 up = modelUp(panels);
  // Front and right: the U normal made perpendicular to up is "right"; any other if none.
  Vec3 right{1, 0, 0};
  for (const Panel3& p : panels)
    if (p.family == 0) {
      right = p.normal;  // every U panel has the same
      break;
    }
  right = right - up * dot(right, up);
  if (norm(right) < 1e-6)
    right = std::fabs(up.x) < 0.9 ? Vec3{1, 0, 0} - up * up.x : Vec3{0, 1, 0} - up * up.y;
  right = normalized(right);
  const Vec3 front = cross(right, up);  // U x W = -V: where a viewer in front stands, as in CAD
  const Vec3 toViewer = (front * std::cos(kAzimuth) + right * std::sin(kAzimuth)) * std::cos(kElevation) +
                        up * std::sin(kElevation);
  const Vec3 screenRight = normalized(cross(up, toViewer));
  return {screenRight, cross(toViewer, screenRight), toViewer};
}

// Model to (supersampled) pixel coordinates: x right, y down, depth growing towards the viewer.
struct Placement {
  View view;
  double x0 = 0, y1 = 0, scale = 1, offsetX = 0, offsetY = 0;
  int width = 0, height = 0;  // supersampled
  double nearest = 0, farthest = 0;

  Vec3 project(const Vec3& p) const {
    return {offsetX + (dot(p, view.right) - x0) * scale, offsetY + (y1 - dot(p, view.up)) * scale,
            dot(p, view.toViewer)};
  }
};

Placement place(const std::vector<Panel3>& panels, int widthPixels) {
  Placement pl;
  pl.view = makeView(panels);
  Box3 box;  // in view coordinates
  for (const Panel3& panel : panels)
    for (const auto& loop : panel.loops)
      for (const Vec3& p : loop)
        box.add({dot(p, pl.view.right), dot(p, pl.view.up), dot(p, pl.view.toViewer)});
  if (box.empty()) throw Error(ErrorKind::BadParameter, "the assembly picture has nothing to draw");
  const double w = widthPixels, margin = kMargin * w;
  const Vec3 size = box.size();
  double scale = (w - 2 * margin) / std::max(size.x, 1e-9);
  double h = size.y * scale + 2 * margin;
  if (h > kMaxAspect * w) {
    h = kMaxAspect * w;
    scale = (h - 2 * margin) / std::max(size.y, 1e-9);
  }
  pl.width = widthPixels * kSupersample;
  pl.height = std::max(1, static_cast<int>(std::ceil(h))) * kSupersample;
  pl.scale = scale * kSupersample;
  pl.x0 = box.min.x;
  pl.y1 = box.max.y;
  pl.offsetX = (pl.width - size.x * pl.scale) / 2;
  pl.offsetY = (pl.height - size.y * pl.scale) / 2;
  pl.nearest = box.max.z;
  pl.farthest = box.min.z;
  return pl;
}

// Rows [lo, hi) of a raster: a band drawn on its own, beside the others.
struct Rows {
  int lo, hi;
};

// A panel as the picture sees it: its loops in pixel coordinates (Placement::project) and
// the rows they span. Projected once a panel: each band of drawAssembly, and each fill of a
// booklet step, had projected every point again (16 bands: 48 projections a point).
struct Projected {
  std::vector<std::vector<Vec3>> loops;
  double left = HUGE_VAL, right = -HUGE_VAL, top = HUGE_VAL, bottom = -HUGE_VAL;
  double nearest = -HUGE_VAL;  // the largest depth, towards the viewer
};

Projected projected(const Placement& pl, const Panel3& panel) {
  Projected out;
  for (const auto& loop : panel.loops) {
    out.loops.emplace_back();
    out.loops.back().reserve(loop.size());
    for (const Vec3& p : loop) {
      const Vec3 q = pl.project(p);
      out.loops.back().push_back(q);
      out.left = std::min(out.left, q.x), out.right = std::max(out.right, q.x);
      out.top = std::min(out.top, q.y), out.bottom = std::max(out.bottom, q.y);
      out.nearest = std::max(out.nearest, q.z);
    }
  }
  return out;
}

// Memory for `n` values of a raster, unset. On Linux in transparent huge pages where the
// system gives them on request (Debian's and Ubuntu's default): the first touch of each
// 4 KB page faults, and on the CI machine touching 58 MB so took 250 ms, with 2 MB pages
// 6 ms.
template <class T>
struct RasterMemory {
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  static std::unique_ptr<T[], Free> make(size_t n) {
    constexpr size_t kHuge = size_t(2) << 20;
    const size_t bytes = std::max<size_t>(n * sizeof(T), 1);
    const bool huge = bytes >= kHuge;
    void* p = huge ? std::aligned_alloc(kHuge, (bytes + kHuge - 1) / kHuge * kHuge) : std::malloc(bytes);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (huge)
      madvise(p, (bytes + kHuge - 1) / kHuge * kHuge, MADV_HUGEPAGE);  // a hint: ignored where refused
#endif
    return std::unique_ptr<T[], Free>(static_cast<T*>(p));
  }
};

// The supersampled picture: colour (0x00RRGGBB) and depth per pixel, eight bytes a pixel
// (float colours took twice the memory). The 1200-pixel picture is 2400 x 3000 of them.
// Made unset; clear() sets a band's rows, so the bands of drawAssembly touch their memory
// on their own cores.
struct Raster {
  int width, height;
  int x0 = 0, y0 = 0;  // where its top left lies in the whole picture's raster (a window's)
  std::unique_ptr<uint32_t[], RasterMemory<uint32_t>::Free> colour;
  std::unique_ptr<float[], RasterMemory<float>::Free> depth;
  Raster(int w, int h)
      : width(w),
        height(h),
        colour(RasterMemory<uint32_t>::make(size_t(w) * h)),
        depth(RasterMemory<float>::make(size_t(w) * h)) {}
  Raster(const Raster& o) : Raster(o.width, o.height) {
    x0 = o.x0, y0 = o.y0;
    std::copy_n(o.colour.get(), size_t(width) * height, colour.get());
    std::copy_n(o.depth.get(), size_t(width) * height, depth.get());
  }
  Raster(Raster&&) = default;
  void clear(Rows band) {
    const size_t from = size_t(band.lo) * width, to = size_t(band.hi) * width;
    std::fill(colour.get() + from, colour.get() + to, kWhite);
    std::fill(depth.get() + from, depth.get() + to, -HUGE_VALF);
  }
};

// Lambert with |n.l|: paper is seen from both sides. Mostly ambient, so both colours stay
// soft; the light comes from the viewer, a little from above and the left.
float shade(const Vec3& normal, const View& view) {
  const Vec3 light = normalized(view.toViewer + view.up * 0.3 - view.right * 0.2);
  return static_cast<float>(0.7 + 0.3 * std::fabs(dot(normalized(normal), light)));
}

// Scanline fill with the even-odd rule (so holes and slots stay open), depth from the plane.
// Highlight: the step's new patch, flat in the highlight colour where it is seen; XRay: the
// same patch again where other paper hides it, half blended, so a reader sees where it
// goes inside the assembly.
enum class Fill { Paper, Highlight, XRay };

void fillPanel(Raster& r, const Placement& pl, const Panel3& panel, const Projected& at, Fill mode,
               Rows band) {
  const Vec3 n = normalized(panel.normal);
  const double facing = dot(n, pl.view.toViewer);
  if (std::fabs(facing) < 1e-6 || panel.loops.empty() || panel.loops[0].empty()) return;  // edge-on
  // Plane n.P = c; a pixel's depth follows from its screen position.
  const double c = dot(n, panel.loops[0][0]);
  const double nx = dot(n, pl.view.right), ny = dot(n, pl.view.up);
  auto depthAt = [&](double px, double py) {
    const double sx = pl.x0 + (px - pl.offsetX) / pl.scale, sy = pl.y1 - (py - pl.offsetY) / pl.scale;
    return (c - nx * sx - ny * sy) / facing;
  };
  // Pixel rows whose centre y + 0.5 lies in [top, bottom), in the band.
  const int row0 = std::max(band.lo, static_cast<int>(std::ceil(at.top - 0.5)));
  const int row1 = std::min(band.hi, static_cast<int>(std::ceil(at.bottom - 0.5)));
  if (row0 >= row1) return;
  // Where the outlines cross each row, as (row, x) in one list sorted by row then x: one
  // allocation a panel, not one a row. Sorted by row by counting (rows are few and known),
  // then each row's few by x: a sort of the whole list was a tenth of the assembly
  // picture's and the booklet's time (ChineseDragon).
  std::vector<std::pair<int, double>> found;
  for (const auto& loop : at.loops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec3& a = loop[i];
      const Vec3& b = loop[(i + 1) % loop.size()];
      if (a.y == b.y) continue;
      const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
      for (int row = std::max(row0, static_cast<int>(std::ceil(lo - 0.5)));
           row < std::min(row1, static_cast<int>(std::ceil(hi - 0.5))); ++row)
        found.emplace_back(row, a.x + (row + 0.5 - a.y) * (b.x - a.x) / (b.y - a.y));
    }
  std::vector<size_t> rowStart(size_t(row1 - row0) + 1, 0);
  for (const auto& c : found) ++rowStart[size_t(c.first - row0) + 1];
  for (size_t r = 1; r < rowStart.size(); ++r) rowStart[r] += rowStart[r - 1];
  std::vector<std::pair<int, double>> crossings(found.size());
  {
    std::vector<size_t> next(rowStart.begin(), rowStart.end() - 1);
    for (const auto& c : found) crossings[next[size_t(c.first - row0)]++] = c;
  }
  for (size_t r = 0; r + 1 < rowStart.size(); ++r)
    std::sort(crossings.begin() + static_cast<std::ptrdiff_t>(rowStart[r]),
              crossings.begin() + static_cast<std::ptrdiff_t>(rowStart[r + 1]));
  // A paper pixel's colour is linear in its depth: channel = base + slope * (nearest - z),
  // the panel's tone and the depth cue's fade folded into two numbers a channel.
  const float tone = shade(n, pl.view);
  const PaperColour paper = paperColour(panel.family);
  const float fadePerDepth = static_cast<float>(kFade / std::max(pl.nearest - pl.farthest, 1e-9));
  float base[3], slope[3];
  const double channels[3] = {paper.r, paper.g, paper.b};
  for (int k = 0; k < 3; ++k) {
    base[k] = tone * float(channels[k]);
    slope[k] = fadePerDepth * (1 - base[k]);
  }
  const double step = depthAt(1.5, 0.5) - depthAt(0.5, 0.5);  // depth is linear along a row
  for (size_t i = 0; i + 1 < crossings.size(); i += 2) {
    // Even-odd: a closed loop crosses each row an even number of times; should rounding
    // ever leave a row odd, its last crossing is dropped rather than paired with the next row.
    while (i + 1 < crossings.size() && crossings[i].first != crossings[i + 1].first) ++i;
    if (i + 1 >= crossings.size()) break;
    const int row = crossings[i].first;
    const int col0 = std::max(r.x0, static_cast<int>(std::ceil(crossings[i].second - 0.5)));
    const int col1 = std::min(r.x0 + r.width, static_cast<int>(std::ceil(crossings[i + 1].second - 0.5)));
    const double z0 = depthAt(col0 + 0.5, row + 0.5);
    // Rows and columns are the whole picture's; a window's memory starts at its origin.
    uint32_t* colour = r.colour.get() + size_t(row - r.y0) * r.width;
    float* depth = r.depth.get() + size_t(row - r.y0) * r.width;
    for (int col = col0, at = col0 - r.x0; col < col1; ++col, ++at) {
      const double z = z0 + (col - col0) * step;
      if (mode == Fill::XRay) {
        if (z < depth[at] - 1e-3) colour[at] = halfway(colour[at], kHighlight);
        continue;
      }
      // The highlight is filled again over itself: its own depth lets it through.
      if (mode == Fill::Highlight ? z < depth[at] - 1e-6 : z <= depth[at]) continue;
      depth[at] = static_cast<float>(z);
      if (mode == Fill::Highlight) {  // flat: every pixel of it is the colour a reader looks for
        colour[at] = kHighlight;
        continue;
      }
      const float behind = static_cast<float>(pl.nearest - z);
      colour[at] =
          packed(base[0] + slope[0] * behind, base[1] + slope[1] * behind, base[2] + slope[2] * behind);
    }
  }
}

// Every pixel of a panel's outlines, drawn `thickness` wide, with the line's depth there.
template <class Fn>
void forEdgePixels(int width, Rows band, const Projected& at, int thickness, Fn&& fn) {
  auto stamp = [&](double x, double y, double z) {
    const int cx = static_cast<int>(std::floor(x - thickness / 2.0 + 0.5));
    const int cy = static_cast<int>(std::floor(y - thickness / 2.0 + 0.5));
    for (int row = std::max(band.lo, cy); row < std::min(band.hi, cy + thickness); ++row)
      for (int col = std::max(0, cx); col < std::min(width, cx + thickness); ++col)
        fn(size_t(row) * width + col, z);
  };
  if (at.bottom + thickness < band.lo || at.top - thickness > band.hi) return;
  for (const auto& loop : at.loops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec3& a = loop[i];
      const Vec3& b = loop[(i + 1) % loop.size()];
      if (std::max(a.y, b.y) + thickness < band.lo || std::min(a.y, b.y) - thickness > band.hi) continue;
      const int steps = std::max(1, static_cast<int>(std::ceil(2 * std::hypot(b.x - a.x, b.y - a.y))));
      for (int s = 0; s <= steps; ++s) {
        const double t = static_cast<double>(s) / steps;
        stamp(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z));
      }
    }
}

// The outlines as dark lines, hidden where other paper is in front: a line passes the depth
// test with a small bias, so it shows on its own panel.
void drawEdges(Raster& r, const Projected& panel, int thickness, double bias, Rows band) {
  forEdgePixels(r.width, band, panel, thickness, [&](size_t at, double z) {
    if (z + bias >= r.depth[at]) r.colour[at] = kEdge;
  });
}

// The same lines kept aside, as the nearest line depth (plus the bias) at each pixel: a
// pixel shows a line once that is at least the paper's depth there, whatever was filled
// after. A growing assembly then draws each panel's lines once, not again at every step.
void keepEdges(std::vector<double>& lines, const Raster& r, const Projected& panel, int thickness,
               double bias) {
  forEdgePixels(r.width, {0, r.height}, panel, thickness,
                [&](size_t at, double z) { lines[at] = std::max(lines[at], z + bias); });
}

// Averages each kSupersample x kSupersample block of a width x height raster into one
// opaque pixel of `out`, the raster's top left going to out's pixel (outX, outY);
// pixel(x, y) is the raster's colour there.
template <class Colour>
void downsampleInto(int width, int height, Picture& out, int outX, int outY, Colour pixel) {
  for (int y = 0; y < height / kSupersample; ++y)
    for (int x = 0; x < width / kSupersample; ++x) {
      uint32_t sum[3] = {0, 0, 0};
      for (int dy = 0; dy < kSupersample; ++dy)
        for (int dx = 0; dx < kSupersample; ++dx) {
          const uint32_t c = pixel(x * kSupersample + dx, y * kSupersample + dy);
          for (int k = 0; k < 3; ++k) sum[k] += (c >> (16 - 8 * k)) & 255;
        }
      constexpr uint32_t n = kSupersample * kSupersample;
      out.pixels[size_t(outY + y) * out.width + outX + x] =
          (sum[0] + n / 2) / n << 16 | (sum[1] + n / 2) / n << 8 | (sum[2] + n / 2) / n;
    }
}

// The whole raster, downsampled on every core in bands of rows.
Picture downsample(const Raster& r) {
  Picture out;
  out.width = r.width / kSupersample;
  out.height = r.height / kSupersample;
  out.pixels.resize(size_t(out.width) * out.height);
  const int bands = 16, rows = (out.height + bands - 1) / bands;
  parallelFor(bands, [&](size_t b) {
    const int y0 = std::min(out.height, static_cast<int>(b) * rows);
    const int y1 = std::min(out.height, (static_cast<int>(b) + 1) * rows);
    downsampleInto(r.width, (y1 - y0) * kSupersample, out, 0, y0,
                   [&](int x, int y) { return r.colour[size_t(y0 * kSupersample + y) * r.width + x]; });
  });
  return out;
}

}  // namespace

PaperColour paperColour(int family) {
  // A warm cream and a soft blue: tell the families apart, and still look like paper.
  return family == 0 ? PaperColour{0.98, 0.89, 0.72} : PaperColour{0.71, 0.82, 0.96};
}

std::vector<Panel3> assemblyPanels(const Arrangement& a, const std::vector<PatchFace>& patches,
                                   double thetaDegrees) {
  std::vector<Panel3> panels;
  for (size_t k = 0; k < patches.size(); ++k) {
    if (patches[k].outline.empty()) continue;
    // The same pose as assemble(): the patch plane at the popped-up pose, then the fold.
    const PatchPlane plane = patchPlane(a, static_cast<int>(k));
    const gp_Trsf pose = foldTransform(a, static_cast<int>(k), thetaDegrees);
    Panel3 panel;
    panel.family = familyIndex(a.scaffold.patches[k].family);
    panel.patch = static_cast<int>(k);
    const gp_Dir n = gp_Dir(plane.normal.x, plane.normal.y, plane.normal.z).Transformed(pose);
    panel.normal = {n.X(), n.Y(), n.Z()};
    for (const Region2d::Loop& loop : patches[k].outline.loops()) {
      panel.loops.emplace_back();
      for (const Vec2& p : loop) {
        const Vec3 q = plane.origin + plane.xAxis * p.x + plane.yAxis * p.y;
        const gp_Pnt moved = gp_Pnt(q.x, q.y, q.z).Transformed(pose);
        panel.loops.back().push_back({moved.X(), moved.Y(), moved.Z()});
      }
    }
    panels.push_back(std::move(panel));
  }
  return panels;
}

namespace {

int edgeThickness(int widthPixels) {  // about one output pixel, a little more in large pictures
  return kSupersample * std::max(1, static_cast<int>(std::lround(widthPixels / 1000.0)));
}
double edgeBias(const Placement& pl, int thickness) {
  return 2e-3 * std::max(pl.nearest - pl.farthest, 1e-9) + thickness / pl.scale;
}
void checkWidth(int widthPixels) {
  if (widthPixels < 16 || widthPixels > 16384)
    throw Error(ErrorKind::BadParameter, "the assembly picture must be 16 to 16384 pixels wide");
}

}  // namespace

struct GrowingAssembly::State {
  const std::vector<Panel3>& panels;
  Placement pl;
  Raster built;               // every panel added so far, filled
  std::vector<double> lines;  // and their outlines (keepEdges)
  Picture shown;              // the two together, downsampled: the picture before a step
  int thickness;
  double bias;
  Picture step;  // what add() returns: `shown`, the last step's box highlighted
  int stepX0 = 0, stepY0 = 0, stepX1 = 0, stepY1 = 0;  // that box, in the picture's pixels

  // `step` as `shown` again where the last step highlighted its box.
  void unhighlight() {
    for (int y = stepY0; y < stepY1; ++y)
      std::copy_n(shown.pixels.begin() + size_t(y) * shown.width + stepX0, stepX1 - stepX0,
                  step.pixels.begin() + size_t(y) * step.width + stepX0);
    stepX0 = stepY0 = stepX1 = stepY1 = 0;
  }

  // A copy of the built raster's box [x0, x1) x [y0, y1) (supersampled pixels, whole
  // blocks); fillPanel draws into it with the whole picture's placement.
  Raster window(int x0, int y0, int x1, int y1) const {
    Raster w(x1 - x0, y1 - y0);
    w.x0 = x0, w.y0 = y0;
    for (int y = y0; y < y1; ++y) {
      std::copy_n(built.colour.get() + size_t(y) * built.width + x0, x1 - x0,
                  w.colour.get() + size_t(y - y0) * w.width);
      std::copy_n(built.depth.get() + size_t(y) * built.width + x0, x1 - x0,
                  w.depth.get() + size_t(y - y0) * w.width);
    }
    return w;
  }
  // Whether a kept edge shows at pixel (x, y) of window w: one lies there, at least as
  // near as the paper.
  bool edgeShows(const Raster& w, int x, int y) const {
    const double line = lines[size_t(w.y0 + y) * built.width + w.x0 + x];
    return line > -HUGE_VAL && line >= w.depth[size_t(y) * w.width + x];
  }
  // The window downsampled into `out`, the kept edges drawn where they show.
  void downsampleWindow(const Raster& w, Picture& out) const {
    downsampleInto(w.width, w.height, out, w.x0 / kSupersample, w.y0 / kSupersample, [&](int x, int y) {
      return edgeShows(w, x, y) ? kEdge : w.colour[size_t(y) * w.width + x];
    });
  }
};

GrowingAssembly::GrowingAssembly(const std::vector<Panel3>& panels, int widthPixels) {
  checkWidth(widthPixels);
  const Placement pl = place(panels, widthPixels);
  const int thickness = edgeThickness(widthPixels);
  Picture blank;
  blank.width = pl.width / kSupersample;
  blank.height = pl.height / kSupersample;
  blank.pixels.assign(size_t(blank.width) * blank.height, kWhite);
  Picture step = blank;
  state_.reset(new State{panels, pl, Raster(pl.width, pl.height),
                         std::vector<double>(size_t(pl.width) * pl.height, -HUGE_VAL), std::move(blank),
                         thickness, edgeBias(pl, thickness), std::move(step)});
  state_->built.clear({0, pl.height});
}

GrowingAssembly::~GrowingAssembly() = default;

// A step changes the picture only inside the new panel's box and its outline's width, so
// only that box is drawn again: on models of many patches, copying and downsampling the
// whole raster at every step had been most of the booklet's time. Nor is the picture
// copied whole for each step: the one returned is kept and mended box by box.
const Picture& GrowingAssembly::add(int panel) {
  State& s = *state_;
  s.unhighlight();
  const Panel3& p = s.panels[panel];
  const Projected seen = projected(s.pl, p);
  const double left = seen.left, right = seen.right, top = seen.top, bottom = seen.bottom;
  if (left > right) return s.step;  // nothing to draw
  const auto block = [](double v, int limit, bool up) {
    const int pixel = static_cast<int>(up ? std::ceil(v) : std::floor(v));
    const int blocks = (up ? pixel + kSupersample - 1 : pixel) / kSupersample;
    return std::clamp(blocks * kSupersample, 0, limit);
  };
  const double reach = s.thickness + 1;  // the outline's stamps spread this far
  const int x0 = block(std::max(0.0, left - reach), s.pl.width, false);
  const int x1 = block(right + reach, s.pl.width, true);
  const int y0 = block(std::max(0.0, top - reach), s.pl.height, false);
  const int y1 = block(bottom + reach, s.pl.height, true);
  fillPanel(s.built, s.pl, p, seen, Fill::Paper, {0, s.built.height});
  keepEdges(s.lines, s.built, seen, s.thickness, s.bias);
  if (x0 >= x1 || y0 >= y1) return s.step;
  Raster w = s.window(x0, y0, x1, y1);
  s.downsampleWindow(w, s.shown);
  fillPanel(w, s.pl, p, seen, Fill::Highlight, {y0, y1});
  // The edges go over the highlight (downsampleWindow), the x-ray over both.
  for (int y = 0; y < w.height; ++y)
    for (int x = 0; x < w.width; ++x)
      if (s.edgeShows(w, x, y)) w.colour[size_t(y) * w.width + x] = kEdge;
  fillPanel(w, s.pl, p, seen, Fill::XRay, {y0, y1});
  // The box in `step` is this step's alone: `shown` there is the picture before the
  // highlight, and the box is given back to it at the next step.
  downsampleInto(w.width, w.height, s.step, x0 / kSupersample, y0 / kSupersample,
                 [&](int x, int y) { return w.colour[size_t(y) * w.width + x]; });
  s.stepX0 = x0 / kSupersample, s.stepY0 = y0 / kSupersample;
  s.stepX1 = s.stepX0 + w.width / kSupersample, s.stepY1 = s.stepY0 + w.height / kSupersample;
  return s.step;
}

Picture drawAssembly(const std::vector<Panel3>& panels, int widthPixels) {
  checkWidth(widthPixels);
  const Placement pl = place(panels, widthPixels);
  Raster raster(pl.width, pl.height);
  const int thickness = edgeThickness(widthPixels);
  // In bands of rows on every core: each band is every panel filled, then every outline,
  // in its own rows, so the picture does not depend on how the bands are shared out.
  // Nearest panels first: paper behind them then fails the depth test before its colour is
  // worked out, which was most of the time on models of many patches.
  std::vector<Projected> seen(panels.size());
  parallelFor(panels.size(), [&](size_t k) { seen[k] = projected(pl, panels[k]); });
  std::vector<std::pair<double, size_t>> nearestFirst;
  for (size_t k = 0; k < panels.size(); ++k) nearestFirst.emplace_back(-seen[k].nearest, k);
  std::stable_sort(nearestFirst.begin(), nearestFirst.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  const int bands = 16, rows = (pl.height + bands - 1) / bands;
  parallelFor(bands, [&](size_t b) {
    const Rows band{std::min(pl.height, static_cast<int>(b) * rows),
                    std::min(pl.height, (static_cast<int>(b) + 1) * rows)};
    raster.clear(band);
    for (const auto& [depth, k] : nearestFirst) fillPanel(raster, pl, panels[k], seen[k], Fill::Paper, band);
    for (const Projected& panel : seen) drawEdges(raster, panel, thickness, edgeBias(pl, thickness), band);
  });
  return downsample(raster);
}

void writePicturePng(const Picture& picture, const std::string& path) {
  writeAtomically(path, [&](const std::string& temporary) {
    writeRgbPng(temporary, picture.pixels.data(), picture.width, picture.height,
                static_cast<size_t>(picture.width));
  });
}

void writeAssemblyPng(const std::vector<Panel3>& panels, const std::string& path, int widthPixels) {
  writePicturePng(drawAssembly(panels, widthPixels), path);
}

}  // namespace sliceform
