// SPDX-License-Identifier: LGPL-2.1-or-later
#include "pipeline/directions.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

#include "support/error.hpp"
#include "support/parallel.hpp"

namespace sliceform {
namespace {

// The objective, on an arrangement's quality: how much of the solid the patches stand for
// (volume IoU) and how it looks from the three sides (silhouette IoU), half each; a frame
// where the model stands on its base gets a bonus worth 0.05 of IoU (a sliceform is put on
// a table W up).
constexpr double kStandsBonus = 0.05;
// A sheet more than the fewest any designed frame needs costs this much score.
constexpr double kSheetCost = 0.01;
// The base footprint: vertices this share of the height above the lowest, and their hull
// at least this share of the model's box seen from above. A round bottom (a ball, a lamp
// on its shade) puts a small cap in the slab, over which the centre of mass stands in an
// unstable balance: 8.7 mm across of a 60 mm ball at 1 %, under 4 % of its box.
constexpr double kBaseSlab = 0.01;
constexpr double kBaseShare = 0.05;
// Turns of the families about the up axis tried first, and then about the best axis.
constexpr double kFirstTurns[] = {0, 45};
constexpr double kMoreTurns[] = {15, 30, 60, 75};

double score(const Quality& q, bool stands) {
  const double silhouette = (q.silhouetteIouU + q.silhouetteIouV + q.silhouetteIouW) / 3;
  return 0.5 * q.volumeIou + 0.5 * silhouette + (stands ? kStandsBonus : 0);
}

Eigen::Vector3d eig(const Vec3& v) {
  return {v.x, v.y, v.z};
}
Vec3 vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

struct Mass {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

// Centre of mass and covariance of the solid the closed mesh bounds, by signed tetrahedra
// from a point near it (its bounding box's centre, for round-off).
Mass massOf(const Mesh& mesh) {
  const Box3 box = mesh.bounds();
  const Eigen::Vector3d o = (eig(box.min) + eig(box.max)) / 2;
  double volume = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = eig(mesh.vertices[t[0]]) - o, b = eig(mesh.vertices[t[1]]) - o,
                          c = eig(mesh.vertices[t[2]]) - o;
    const double det = a.dot(b.cross(c));
    const Eigen::Vector3d s = a + b + c;
    volume += det / 6;
    first += det / 24 * s;
    second += det / 120 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  Mass m;
  if (std::abs(volume) < 1e-12) return m;
  const Eigen::Vector3d mean = first / volume;
  m.centre = mean + o;
  m.covariance = second / volume - mean * mean.transpose();
  return m;
}

// Principal axes, largest spread first, each signed so that the mesh's vertices lean
// toward its positive side (third moment): the same axes for a turned copy of the model.
std::array<Vec3, 3> principalAxes(const Mesh& mesh, const Mass& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m.covariance);
  std::array<Vec3, 3> axes;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d e = solver.eigenvectors().col(2 - k).normalized();
    double skew = 0;
    for (const Vec3& p : mesh.vertices) skew += std::pow((eig(p) - m.centre).dot(e), 3);
    axes[k] = vec(skew < 0 ? -e : e);
  }
  return axes;
}

double cross2(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain: the convex hull, counter-clockwise.
std::vector<Vec2> convexHull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(),
            [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  std::vector<Vec2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross2(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross2(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// Two unit vectors completing `w` to a right-handed frame (a x b = w); `a` along `hint`
// projected off w, or any direction when the hint lies along w.
std::pair<Vec3, Vec3> planeOf(const Vec3& w, const Vec3& hint) {
  Vec3 a = hint - w * dot(hint, w);
  if (norm(a) < 1e-6) a = std::abs(w.x) < 0.9 ? Vec3{1, 0, 0} - w * w.x : Vec3{0, 1, 0} - w * w.y;
  a = normalized(a);
  return {a, cross(w, a)};
}

std::string degrees(double d) {
  char text[16];
  std::snprintf(text, sizeof text, "%g°", d);
  return text;
}

// An up axis: W, the direction turns start from, and whether the model stands on it.
struct UpAxis {
  std::string name;
  Vec3 w, hint;
  bool stands = false;
};

FrameTrial turned(const std::vector<UpAxis>& axes, int axis, double turn) {
  const UpAxis& x = axes[axis];
  const auto [a, b] = planeOf(x.w, x.hint);
  const double r = turn * M_PI / 180;
  FrameTrial t;
  t.name = x.name + " up, " + degrees(turn);
  t.u = normalized(a * std::cos(r) + b * std::sin(r));
  t.v = normalized(cross(x.w, t.u));
  t.axis = axis, t.turn = turn;
  t.stands = x.stands;
  return t;
}

bool sameFrame(const FrameTrial& a, const FrameTrial& b) {
  return std::abs(dot(a.u, b.u)) > 1 - 1e-9 && std::abs(dot(a.v, b.v)) > 1 - 1e-9;
}

// What an estimate arranges, but its directions (each trial's own): the given arrangement
// parameters at no more than kEstimateSlices slices a direction. Edits that change none of
// it (Thickness, Clearance, Kerf; Slices from 128 to 129) leave every estimate as it was.
ArrangementParams estimateParams(ArrangementParams p) {
  p.u = ArrangementParams{}.u, p.v = ArrangementParams{}.v;
  p.slices = std::min(p.slices, kEstimateSlices);
  p.interval = 0;
  return p;
}

// The arrangement at kEstimateSlices in the trial's frame, scored; `failure` gets what it
// threw.
void estimate(const Model& model, const ArrangementParams& params, FrameTrial& t,
              std::exception_ptr& failure) {
  ArrangementParams p = params;
  p.u = t.u, p.v = t.v;
  try {
    const Arrangement a = arrange(model, p);
    t.estimate = a.quality;
    t.estimatePatches = static_cast<int>(a.scaffold.patches.size());
    t.score = a.certificate.stable ? score(a.quality, t.stands) : -1;
    if (!a.certificate.stable) t.failure = "not stable: " + a.certificate.reason;
  } catch (const Error& e) {
    t.score = -1;
    t.failure = e.what();
    failure = std::current_exception();
  }
}

// A trial as its estimate left it: what its full design added, if it had one, dropped.
FrameTrial asEstimated(const FrameTrial& trial) {
  FrameTrial t = trial;
  const FrameTrial none;
  t.designed = none.designed, t.buildable = none.buildable, t.quality = none.quality;
  t.patches = none.patches, t.sheets = none.sheets, t.designScore = none.designScore;
  t.laidOut = none.laidOut;
  if (t.score >= 0) t.failure.clear();  // a design's failure; an estimate that failed scores -1
  return t;
}

// Trials in the order they are preferred: score, then fewer patches, then as tried.
std::vector<size_t> ranked(const std::vector<FrameTrial>& trials) {
  std::vector<size_t> order(trials.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (trials[a].score != trials[b].score) return trials[a].score > trials[b].score;
    return trials[a].estimatePatches < trials[b].estimatePatches;
  });
  return order;
}

}  // namespace

bool standsUp(const Mesh& mesh, const Vec3& up) {
  if (mesh.vertices.empty()) return false;
  const Vec3 w = normalized(up);
  const Interval h = mesh.extent(w);
  const auto [a, b] = planeOf(w, {1, 0, 0});
  std::vector<Vec2> base;
  for (const Vec3& p : mesh.vertices)
    if (dot(p, w) <= h.lo + kBaseSlab * (h.hi - h.lo)) base.push_back({dot(p, a), dot(p, b)});
  const std::vector<Vec2> hull = convexHull(base);
  if (hull.size() < 3) return false;
  double hullArea = 0;
  for (size_t i = 0; i < hull.size(); ++i)
    hullArea += cross2({0, 0}, hull[i], hull[(i + 1) % hull.size()]) / 2;
  const Interval ea = mesh.extent(a), eb = mesh.extent(b);
  if (hullArea < kBaseShare * (ea.hi - ea.lo) * (eb.hi - eb.lo)) return false;
  const Vec3 c = vec(massOf(mesh).centre);
  const Vec2 q{dot(c, a), dot(c, b)};
  for (size_t i = 0; i < hull.size(); ++i)
    if (cross2(hull[i], hull[(i + 1) % hull.size()], q) <= 0) return false;
  return true;
}

namespace {

// The up axes: the principal ones, then the file's that are not one of them (a model drawn
// square to its axes has them once: so a turned copy is offered the same frames), each
// signed the way the model stands on it, where only one way does.
std::vector<UpAxis> upAxes(const Model& model) {
  const Mass m = massOf(model.mesh);
  const std::array<Vec3, 3> principal = principalAxes(model.mesh, m);
  std::vector<UpAxis> axes;
  for (int k = 0; k < 3; ++k)
    axes.push_back({"principal " + std::to_string(k + 1), principal[k], principal[k == 0 ? 1 : 0]});
  // The file's axes, the next one in turn as the families' first direction: Z up gives the
  // default frame, U = X and V = Y.
  const Vec3 file[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const char* names[3] = {"X", "Y", "Z"};
  for (int k = 0; k < 3; ++k)
    if (std::none_of(principal.begin(), principal.end(),
                     [&](const Vec3& p) { return std::abs(dot(p, file[k])) > 1 - 1e-6; }))
      axes.push_back({names[k], file[k], file[(k + 1) % 3]});
  for (UpAxis& axis : axes) {
    const bool up = standsUp(model.mesh, axis.w), down = standsUp(model.mesh, axis.w * -1.0);
    if (down && !up) axis.w = axis.w * -1.0, axis.name = "-" + axis.name;
    axis.stands = up || down;
  }
  return axes;
}

std::vector<FrameTrial> framesAbout(const std::vector<UpAxis>& axes, int axis, const double* turns, size_t n,
                                    const std::vector<FrameTrial>& tried) {
  std::vector<FrameTrial> out;
  for (size_t k = 0; k < n; ++k) {
    FrameTrial t = turned(axes, axis, turns[k]);
    const auto same = [&](const FrameTrial& o) { return sameFrame(o, t); };
    if (std::none_of(tried.begin(), tried.end(), same) && std::none_of(out.begin(), out.end(), same))
      out.push_back(std::move(t));
  }
  return out;
}

}  // namespace

std::vector<FrameTrial> candidateFrames(const Model& model) {
  const std::vector<UpAxis> axes = upAxes(model);
  std::vector<FrameTrial> out;
  for (int a = 0; a < static_cast<int>(axes.size()); ++a)
    for (FrameTrial& t : framesAbout(axes, a, kFirstTurns, std::size(kFirstTurns), out))
      out.push_back(std::move(t));
  return out;
}

Design designInBestFrame(const Model& model, DesignParams params, DirectionChoice& choice,
                         const Progress& progress, const PatchesReady& patchesReady,
                         const Deadline* runDeadline, const Design* earlier, const Design* made) {
  const Deadline own(runDeadline ? 0 : params.timeLimit);
  const Deadline& deadline = runDeadline ? *runDeadline : own;
  const auto start = std::chrono::steady_clock::now();
  choice = DirectionChoice{};
  choice.automatic = true;
  std::vector<FrameTrial>& trials = choice.trials;
  const ArrangementParams estimated = estimateParams(params.arrangement);
  choice.estimatedWith = estimated;
  // The estimates read the model and estimateParams() alone: a design of the same model
  // whose choice was estimated from the same ones lends them, so a Thickness, Clearance,
  // Kerf or Slices edit in FreeCAD designs only the best frame again.
  const DirectionChoice* was = earlier && earlier->directions.automatic ? &earlier->directions : nullptr;
  if (was && was->estimatedWith == estimated) {
    choice.estimatesTaken = true;
    for (const FrameTrial& w : was->trials) trials.push_back(asEstimated(w));
  } else {
    const std::vector<UpAxis> axes = upAxes(model);
    for (int a = 0; a < static_cast<int>(axes.size()); ++a)
      for (FrameTrial& t : framesAbout(axes, a, kFirstTurns, std::size(kFirstTurns), trials))
        trials.push_back(std::move(t));
    std::vector<std::exception_ptr> failures(trials.size());
    parallelFor(trials.size(), [&](size_t k) { estimate(model, estimated, trials[k], failures[k]); });
    // No frame at all: the model's own fault (an open mesh, too thin for the rules), said as
    // the given frame would have said it.
    if (std::all_of(trials.begin(), trials.end(), [](const FrameTrial& t) { return t.score < 0; }))
      for (const std::exception_ptr& f : failures)
        if (f) std::rethrow_exception(f);
    // The families turned further about the best frame's up axis.
    const size_t first = trials.size();
    for (FrameTrial& t :
         framesAbout(axes, trials[ranked(trials).front()].axis, kMoreTurns, std::size(kMoreTurns), trials))
      trials.push_back(std::move(t));
    failures.resize(trials.size());
    parallelFor(trials.size() - first,
                [&](size_t k) { estimate(model, estimated, trials[first + k], failures[first + k]); });
  }
  const double estimating =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  // The best in full; the runner-up only when the best cannot be built (designing close
  // runners-up too took 4-10 times one design on fandisk, the dragon and man), or when its
  // layout fails (a patch larger than the sheet). Buildable first, then the score on the
  // full design, sheets counted. Buildability reads nothing of the layout, so a design is
  // laid out only while it can still win: a buildable runner-up wins over the best without
  // the best's layout (anchor_dense: 0.3 s of 2.8).
  const std::vector<size_t> order = ranked(trials);
  std::vector<std::pair<size_t, Design>> designs;  // those still in the running
  std::exception_ptr firstFailure;
  int attempted = 0;
  const auto designsStart = std::chrono::steady_clock::now();
  const auto failed = [&](FrameTrial& t, const Error& e) {  // in a handler: e is the current one
    t.failure = e.what();
    if (!firstFailure) firstFailure = std::current_exception();
  };
  // Lays out trials[k]'s design; false, with the trial's failure, when that fails.
  const auto laidOut = [&](size_t k, Design& d) {
    try {
      layOutDesign(d, params.sheet, progress);
    } catch (const Error& e) {
      failed(trials[k], e);
      return false;
    }
    trials[k].laidOut = true;
    trials[k].sheets = d.layout.packing.sheets;
    return true;
  };
  bool settled = false;  // a buildable design is laid out: it is the one
  for (size_t r = 0; r < order.size() && r < 2 && !settled; ++r) {
    FrameTrial& t = trials[order[r]];
    if (t.score < 0) break;
    if (r == 1 && deadline.passed()) break;  // the time is up: the best frame's design stands
    DesignParams p = params;
    p.arrangement.u = t.u, p.arrangement.v = t.v;
    ++attempted;
    try {
      // The same design again, where it was made already (Motor-c.brep: the file's axes rank
      // first, 15 s).
      const bool known = made && made->arrangement.params.u == t.u && made->arrangement.params.v == t.v;
      Design d = known ? *made : designPatches(model, p, progress, &deadline, earlier);
      t.designed = true;
      t.buildable = designProblems(d).empty();
      t.quality = d.arrangement.quality;
      t.patches = static_cast<int>(d.patches.size());
      // A buildable design's 3D files begin beside its layout, as the file's axes' do: the
      // layout almost always stands, and otherwise the next design heard of replaces them
      // (occ/Top.brep: the STEP file's last 0.9 s ran alone after the other files).
      if (t.buildable && patchesReady) patchesReady(d);
      if (!t.buildable) {
        designs.emplace_back(order[r], std::move(d));
      } else if (laidOut(order[r], d)) {
        designs.clear();  // an unbuildable best before it loses without a layout
        designs.emplace_back(order[r], std::move(d));
        settled = true;
      }
    } catch (const Error& e) {
      failed(t, e);
    }
  }
  // None buildable: each laid out, and sheets decide.
  if (!settled)
    designs.erase(
        std::remove_if(designs.begin(), designs.end(), [&](auto& e) { return !laidOut(e.first, e.second); }),
        designs.end());
  if (designs.empty()) {
    if (firstFailure) std::rethrow_exception(firstFailure);
    throw Error(ErrorKind::Unbuildable,
                model.source + ": no slicing directions tried give a design: " +
                    (trials.empty() ? std::string("none tried") : trials[order[0]].failure));
  }
  const double designing =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - designsStart).count();
  for (FrameTrial& t : trials)
    if (t.designed && !t.laidOut) t.designScore = score(t.quality, t.stands);
  int fewest = designs.front().second.layout.packing.sheets;
  for (const auto& [k, d] : designs) fewest = std::min(fewest, d.layout.packing.sheets);
  size_t won = 0;
  for (size_t i = 0; i < designs.size(); ++i) {
    FrameTrial& t = trials[designs[i].first];
    t.designScore = score(t.quality, t.stands) - kSheetCost * (t.sheets - fewest);
    const FrameTrial& w0 = trials[designs[won].first];
    if (i > 0 &&
        (t.buildable > w0.buildable || (t.buildable == w0.buildable && t.designScore > w0.designScore)))
      won = i;
  }
  choice.chosen = static_cast<int>(designs[won].first);
  const FrameTrial& c = trials[choice.chosen];
  char why[256];
  const auto designed =
      std::count_if(trials.begin(), trials.end(), [](const FrameTrial& t) { return t.designed; });
  std::snprintf(why, sizeof why, "%s: best of %zu frames (score %.3f%s), %zu designed in full%s",
                c.name.c_str(), trials.size(), c.designScore, c.stands ? ", stands on its base" : "",
                static_cast<size_t>(designed), c.buildable ? "" : "; none could be built");
  choice.why = why;
  Design d = std::move(designs[won].second);
  d.directions = choice;
  // The stages' times add up to the run's: the frames designed and not chosen are a row.
  double chosenMs = 0;
  for (const StageTime& s : d.timings) chosenMs += s.ms;
  d.timings.insert(d.timings.begin(), {"directions (estimates)", estimating});
  if (attempted > 1)
    d.timings.insert(d.timings.begin() + 1,
                     {"directions (frames designed, not chosen)", std::max(0.0, designing - chosenMs)});
  // With the design returned, whatever was heard of before: where no design could be built,
  // the one the sheets chose (a buildable one's was heard of before its layout).
  if (patchesReady) patchesReady(d);
  return d;
}

}  // namespace sliceform
