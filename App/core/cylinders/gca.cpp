// SPDX-License-Identifier: LGPL-2.1-or-later
#include "cylinders/gca.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cylinders/partition_bounds.hpp"
#include "geometry/simplify.hpp"
#include "support/error.hpp"
#include "support/parallel.hpp"

namespace sliceform {
namespace {

constexpr double kErrorTolerance = 0.02;  // mm
// The longest runs measured first, in slices, and as a share of the edge's, before
// runsToMeasure() asks for longer ones. The partitions of 128 slices mostly take runs of 3 to
// 10 (stanford-bunny: 17 runs of 123). Unions made on stanford-bunny, ChineseDragon,
// rocker-arm, Top and femur, of 35.5k with every run: 8 slices first, 22.9k in 18 rounds;
// 12, 24.0k in 9; 16, 27.2k; 24, 31.4k. Spot at 512 slices took a tenth of an edge.
constexpr int kFirstRun = 12;
constexpr double kFirstRunShare = 0.1;
// Rounds of runs asked for before every row is measured to its end: equal sections tie
// their runs' errors at 0, and a round may settle a few ties only (on the 58 files, a CAD
// edge of 66 slices took the most, 8).
constexpr int kMaxRounds = 16;

}  // namespace

double cylinderError(const std::vector<Region2d>& patches, int i, int j, double ds) {
  std::vector<Region2d> run(patches.begin() + i, patches.begin() + j + 1);
  const double unionArea = Region2d::uniteAll(run).area();
  double sum = 0;
  for (const Region2d& p : run) sum += unionArea - p.area();
  return ds * sum;
}

std::vector<std::pair<int, int>> partitionPatches(const std::vector<Region2d>& patches, double ds,
                                                  double tauA, int minRun) {
  if (!(tauA >= 0)) throw Error(ErrorKind::BadParameter, "tauA must be zero or positive");
  const int n = static_cast<int>(patches.size());
  if (n == 0) return {};
  minRun = std::max(1, minRun);
  if (n < 2 * minRun) return {{0, n - 1}};  // no two groups fit: one cylinder
  // The errors are measured on the patches simplified within kErrorTolerance: the unions
  // below are the stage's cost (n x run length of them), and a mesh's sections carry a
  // point at every triangle they cross. What that changes in an error is at most
  // tolerance x perimeter x ds a patch, a small fraction of the budget.
  std::vector<Region2d> coarse(n);
  parallelFor(static_cast<size_t>(n), [&](size_t k) { coarse[k] = simplified(patches[k], kErrorTolerance); });
  std::vector<double> area(n);
  double volume = 0;
  std::vector<double> areaBefore(n + 1, 0);
  for (int k = 0; k < n; ++k) {
    volume += (area[k] = coarse[k].area()) * ds;
    areaBefore[k + 1] = areaBefore[k] + area[k];
  }
  const double budget = tauA * volume;

  // err(i, j) for every run, with the union grown one patch at a time. The error only
  // grows as a run gets longer, so a run is not extended past the budget once it is
  // `measured` slices long: longer runs can never be part of an answer (infinite error).
  // Nor past upTo[i], for now: see below.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> err(n, std::vector<double>(n, kInf));
  // Each row's union so far, its areas' sum and the last patch in it: measuring longer
  // runs goes on from there, with the same unions in the same order and so the same
  // errors, not from the row's first patch again (femur.off: that was half the stage).
  struct Row {
    Region2d united;
    double sumArea = 0;
    int last = -1;  // none yet
  };
  std::vector<Row> rows(n);
  std::vector<std::vector<double>> unionArea(n);  // per row, after each patch
  std::vector<int> last(n);
  std::vector<char> open(n, 1);
  // `measured`: minRun while a partition may fit the budget. Where none does, any edge
  // splits into runs of minRun to 2 minRun - 1 slices: those are measured all, and the
  // partition with the least error taken. (Seldom: measuring them always doubled the
  // stage's time on stanford-bunny.)
  int measured = minRun;
  // Whether the budget ended row i: its last run is over it and `measured` long at least.
  const auto ended = [&](int i) {
    const int j = rows[i].last;
    return j >= i && err[i][j] > budget && j - i + 1 >= measured;
  };
  const auto measure = [&](const std::vector<int>& upTo) {
    // Rows are independent: one per core, each writing only its own row.
    parallelFor(static_cast<size_t>(n), [&](size_t index) {
      const int i = static_cast<int>(index);
      Row& row = rows[i];
      if (ended(i)) return;
      for (int j = std::max(row.last + 1, i); j <= upTo[i]; ++j) {
        row.united = j == i ? coarse[i] : row.united.unite(coarse[j]);
        row.sumArea += area[j];
        unionArea[i].push_back(row.united.area());
        err[i][j] = ds * ((j - i + 1) * unionArea[i].back() - row.sumArea);
        row.last = j;
        if (err[i][j] > budget && j - i + 1 >= measured) break;
      }
    });
  };
  // D[m][i]: least error of patches i..n-1 in m groups (eq. 2, suffix form); choice[m][i]
  // the end of the first group. Stop at the first m whose best error fits the budget;
  // `least` is the group count with the least error when none does.
  std::vector<std::vector<double>> best;
  std::vector<std::vector<int>> choice;
  int least = -1;
  const auto solve = [&] {
    best.assign(1, std::vector<double>(n + 1, kInf));
    choice.assign(1, std::vector<int>(n + 1, -1));
    best[0][n] = 0;
    least = -1;
    for (int m = 1; m * minRun <= n; ++m) {
      best.emplace_back(n + 1, kInf);
      choice.emplace_back(n + 1, -1);
      for (int i = 0; i < n; ++i) {
        for (int k = i + minRun - 1; k < n && err[i][k] < kInf; ++k) {
          const double total = err[i][k] + best[m - 1][k + 1];
          if (total < best[m][i]) {
            best[m][i] = total;
            choice[m][i] = k;
          }
        }
      }
      if (best[m][0] <= budget) return m;
      if (best[m][0] < kInf && (least < 0 || best[m][0] < best[least][0])) least = m;
    }
    return -1;
  };
  const auto groupsOf = [&](int m) {
    std::vector<std::pair<int, int>> groups;
    for (int i = 0, left = m; i < n; --left) {
      const int k = choice[left][i];
      groups.emplace_back(i, k);
      i = k + 1;
    }
    return groups;
  };
  // Most runs measured that far are never taken: an answer of 17 runs of 123 slices had
  // rows of 26 within the budget (stanford-bunny). So the runs up to firstRun slices
  // first, and longer ones only where runsToMeasure() finds that they could change the
  // answer; every run where no partition of these fits. The answer is the one every run
  // would give, to the bit: the same unions in the same order, and the same DP.
  const int firstRun = std::max(kFirstRun, static_cast<int>(kFirstRunShare * n));
  std::vector<int> upTo(n);
  for (int i = 0; i < n; ++i) upTo[i] = std::min(n - 1, i + firstRun - 1);
  int fits = -1;
  bool noneFits = false;  // the runs of 2 minRun - 1 slices are asked for
  for (int round = 0;; ++round) {
    measure(upTo);
    fits = solve();
    bool any = false;  // a row stopped short of where the budget stops it
    for (int i = 0; i < n; ++i) {
      last[i] = rows[i].last;
      open[i] = last[i] < n - 1 && !ended(i);
      any = any || open[i];
    }
    std::vector<std::pair<int, int>> runs;
    const int answer = fits > 0 ? fits : noneFits ? least : 0;
    if (any && answer >= 0 && round < kMaxRounds) {
      runs =
          runsToMeasure({err, unionArea, last, open, areaBefore, ds, budget, minRun}, answer, best, choice);
    } else if (any) {  // every open row to its end
      for (int i = 0; i < n; ++i)
        if (open[i]) runs.emplace_back(i, n - 1);
    }
    if (runs.empty() && (fits > 0 || noneFits)) break;
    if (runs.empty()) {
      noneFits = true, measured = 2 * minRun - 1;
      for (int i = 0; i < n; ++i) upTo[i] = std::min(n - 1, std::max(upTo[i], i + measured - 1));
    }
    // Each row asked for to that run at least, and twice as long: fewer rounds.
    for (const auto& [i, k] : runs) upTo[i] = std::min(n - 1, std::max({upTo[i], k, 2 * last[i] - i + 1}));
  }
  if (fits > 0) return groupsOf(fits);
  if (least < 0) throw Error(ErrorKind::Geometry, "cylinder approximation found no partition");
  return groupsOf(least);
}

std::vector<Cylinder> approximateCylinders(const ReebGraph& graph, Family family, double ds, double tauA,
                                           int minRun) {
  std::vector<Cylinder> out;
  std::vector<std::pair<int, int>> runs;  // of each cylinder, in its edge's patches
  for (size_t e = 0; e < graph.edges.size(); ++e) {
    const ReebEdge& edge = graph.edges[e];
    for (const auto& [i, j] : partitionPatches(edge.patches, ds, tauA, minRun)) {
      Cylinder c;
      c.family = family;
      c.reebEdge = static_cast<int>(e);
      c.firstSlice = edge.firstSlice + i;
      c.lastSlice = edge.firstSlice + j;
      out.push_back(std::move(c));
      runs.emplace_back(i, j);
    }
  }
  // The sections, on every core: each is the union of its run's exact patches, and its error
  // (cylinderError) is measured against that very union, not a second one made the same way.
  parallelFor(out.size(), [&](size_t k) {
    Cylinder& c = out[k];
    const std::vector<Region2d>& patches = graph.edges[c.reebEdge].patches;
    const auto [i, j] = runs[k];
    c.section = Region2d::uniteAll({patches.begin() + i, patches.begin() + j + 1});
    const double unionArea = c.section.area();
    double sum = 0;
    for (int m = i; m <= j; ++m) sum += unionArea - patches[m].area();
    c.error = ds * sum;
  });
  return out;
}

}  // namespace sliceform
