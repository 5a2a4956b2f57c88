// SPDX-License-Identifier: LGPL-2.1-or-later
#include "verify/certificate.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "support/per_family.hpp"

namespace sliceform {

Certificate certify(const std::vector<BarPatch>& patches, const std::vector<PinHinge>& hinges) {
  Certificate c;
  c.patches = static_cast<int>(patches.size());
  if (patches.size() < 2) {
    c.reason = "a scaffold needs at least two patches";
    return c;
  }
  // Several hinges of one pair lie on one line parallel to W: one pin in the plane.
  std::set<std::pair<int, int>> pins;
  for (const PinHinge& h : hinges) {
    if (h.a < 0 || h.b < 0 || h.a >= c.patches || h.b >= c.patches) {
      c.reason = "a hinge names a patch that does not exist";
      return c;
    }
    if (patches[h.a].family == patches[h.b].family) {
      c.reason = "a hinge joins two patches of the same family";
      return c;
    }
    pins.insert(std::minmax(h.a, h.b));
  }
  c.pins = static_cast<int>(pins.size());

  // Centre and scale each axis by its spread: moving the origin is a change of basis of the
  // velocities (rank unchanged), and it keeps patches that are close together but far from
  // the origin apart in the numbers (occ/Pump_Nut.brep: V-patches 0.3 mm apart at 677 mm
  // looked identical, and a stable scaffold was called wobbly).
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (const BarPatch& p : patches) {
    const int axis = familyIndex(p.family);
    lo[axis] = std::min(lo[axis], p.position);
    hi[axis] = std::max(hi[axis], p.position);
  }
  double centre[2], spread = 0;
  for (int axis = 0; axis < 2; ++axis) {
    centre[axis] = lo[axis] <= hi[axis] ? 0.5 * (lo[axis] + hi[axis]) : 0.0;
    if (lo[axis] <= hi[axis]) spread = std::max(spread, hi[axis] - lo[axis]);
  }
  const double scale = spread > 0 ? 2.0 / spread : 1.0;

  // Unknowns: (vx, vy, omega) of every patch but patch 0, which is held. Each pin gives two
  // rows with at most six entries: build M sparse.
  const int n = c.patches;
  std::vector<Eigen::Triplet<double>> entries;
  int row = 0;
  for (const auto& [i, j] : pins) {
    const BarPatch& u = patches[i].family == Family::U ? patches[i] : patches[j];
    const BarPatch& v = patches[i].family == Family::U ? patches[j] : patches[i];
    const double px = (u.position - centre[0]) * scale, py = (v.position - centre[1]) * scale;  // the pin
    // Velocity of body k at p: (vx - omega * py, vy + omega * px); rows: v_i(p) - v_j(p) = 0.
    for (const auto& [body, sign] : {std::make_pair(i, 1.0), std::make_pair(j, -1.0)}) {
      if (body == 0) continue;
      const int col = 3 * (body - 1);
      entries.emplace_back(row, col, sign);
      entries.emplace_back(row, col + 2, -sign * py);
      entries.emplace_back(row + 1, col + 1, sign);
      entries.emplace_back(row + 1, col + 2, sign * px);
    }
    row += 2;
  }
  Eigen::SparseMatrix<double> m(2 * static_cast<int>(pins.size()), 3 * (n - 1));
  m.setFromTriplets(entries.begin(), entries.end());
  // rank(M) = rank(M^T M), and M^T M is only 3(n-1) square however many pins there are:
  // count its eigenvalues that vanish next to the largest.
  const Eigen::MatrixXd normal = Eigen::MatrixXd(Eigen::SparseMatrix<double>(m.transpose() * m));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(normal, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd values = eigen.eigenvalues();
  const double largest = values.size() ? values.cwiseAbs().maxCoeff() : 0.0;
  int vanishing = 0;
  for (Eigen::Index k = 0; k < values.size(); ++k) vanishing += values[k] <= 1e-12 * largest ? 1 : 0;
  c.nullity = largest > 0 ? vanishing : static_cast<int>(m.cols());
  c.stable = c.nullity == 1;
  if (!c.stable) {
    c.reason = c.nullity == 0 ? "the scaffold cannot fold (no motion left with one patch held)"
                              : "the scaffold wobbles: " + std::to_string(c.nullity - 1) +
                                    " motion(s) beyond the fold with one patch held";
  }
  return c;
}

}  // namespace sliceform
