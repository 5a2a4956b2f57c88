// SPDX-License-Identifier: LGPL-2.1-or-later
#include "cylinders/partition_bounds.hpp"

#include <algorithm>
#include <limits>

namespace sliceform {
namespace {

// How far below the bound a longer run's error is taken to be, as a share of the budget:
// areas rounded to Clipper's units, sums in another order. On Top, Bottom, fandisk, knot2,
// spot and stanford-bunny, a run's error is never below its parts' errors summed by more
// than 2.2e-16 of the budget.
constexpr double kSlack = 1e-6;

// Per run start i, from i on: err(i, k) where measured, else a lower bound of it; up to the
// first run whose value is over `over` by more than the slack (the error grows with the
// run: so are all longer ones). A run's union holds every union measured within it,
// so its error is at least ds * (length * the largest of their areas - the patches' areas).
std::vector<std::vector<double>> lowerBounds(const MeasuredRuns& at, double over, double slack) {
  const int n = static_cast<int>(at.err.size());
  std::vector<std::vector<double>> out(n);
  for (int i = 0; i < n; ++i)
    for (int k = i; k < n; ++k) {
      double e = 0;
      if (k <= at.last[i]) {
        e = at.err[i][k];
      } else if (!at.open[i]) {
        break;  // the budget ended the row: no longer run counts
      } else {
        double largest = 0;
        for (int a = i; a <= k; ++a)
          largest = std::max(largest, at.unionArea[a][std::min(at.last[a], k) - a]);
        e = at.ds * ((k - i + 1) * largest - (at.areaBefore[k + 1] - at.areaBefore[i])) - slack;
      }
      if (e > over + slack) break;
      out[i].push_back(e);
    }
  return out;
}

}  // namespace

// The answer's group count m is the first that fits the budget; where none does, the first
// with the least error, or 0 while that none fits is what is to be shown. With T the
// budget, or that least error where it is more:
// (a) No other count wins: a lower bound of its least error is over T where it comes
// before m (or m is 0), and not under T where it comes after (ties go to the first).
// Where m fits, the counts after it are never asked.
// (b) Along the answer, no run not taken could have won: a run before the one taken (the
// DP keeps the first least total) totals more, one after it no less.
// A run over T is in no total within it: such runs are left out. Where a bound fails, the
// runs not measured in the partition that gives it are asked for, those of every bound
// that fails at once (a round of measuring and solving each).
std::vector<std::pair<int, int>> runsToMeasure(const MeasuredRuns& at, int m,
                                               const std::vector<std::vector<double>>& best,
                                               const std::vector<std::vector<int>>& choice) {
  const int n = static_cast<int>(at.err.size());
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const bool fits = m > 0 && best[m][0] <= at.budget;
  const double over = m > 0 ? std::max(at.budget, best[m][0]) : at.budget;  // T
  const double slack = at.budget * kSlack;
  const std::vector<std::vector<double>> lower = lowerBounds(at, over, slack);
  const int counts = fits ? m - 1 : n / at.minRun;  // the other counts asked, from 1
  // least[g][i]: a lower bound of the least error of patches i..n-1 in g groups, and
  // through[g][i] the end of the first group in the partition that gives it.
  std::vector<std::vector<double>> least(counts + 1, std::vector<double>(n + 1, kInf));
  std::vector<std::vector<int>> through(counts + 1, std::vector<int>(n + 1, -1));
  least[0][n] = 0;
  // Per row, the longest run asked for; false where a bound fails on measured runs alone,
  // which then needs every run.
  std::vector<int> asked(n, -1);
  const auto ask = [&](int g, int i, int k) {
    bool any = false;
    while (true) {
      if (k > at.last[i]) asked[i] = std::max(asked[i], k), any = true;
      i = k + 1, --g;
      if (g == 0 || i >= n || (k = through[g][i]) < 0) break;
    }
    return any;
  };
  const auto everyRun = [&] {
    std::vector<std::pair<int, int>> all;
    for (int r = 0; r < n; ++r)
      if (at.open[r]) all.emplace_back(r, n - 1);
    return all;
  };
  for (int g = 1; g <= counts; ++g) {
    for (int i = 0; i < n; ++i)
      for (int k = i + at.minRun - 1; k - i < static_cast<int>(lower[i].size()); ++k)
        if (lower[i][k - i] + least[g - 1][k + 1] < least[g][i])
          least[g][i] = lower[i][k - i] + least[g - 1][k + 1], through[g][i] = k;
    const bool before = m == 0 || g < m;
    const bool wins = g != m && (before ? !(least[g][0] > over) : least[g][0] < over);
    if (wins && !ask(g, 0, through[g][0])) return everyRun();  // (a)
  }
  for (int g = m, i = 0; g > 0; --g) {  // (b)
    const int taken = choice[g][i];
    const double total = at.err[i][taken] + best[g - 1][taken + 1];
    for (int k = i + at.minRun - 1; k - i < static_cast<int>(lower[i].size()); ++k) {
      const double other = lower[i][k - i] + least[g - 1][k + 1];
      if (k != taken && (k < taken ? !(other > total) : other < total) && !ask(g, i, k)) return everyRun();
    }
    i = taken + 1;
  }
  std::vector<std::pair<int, int>> runs;
  for (int r = 0; r < n; ++r)
    if (asked[r] >= 0) runs.emplace_back(r, asked[r]);
  return runs;
}

}  // namespace sliceform
