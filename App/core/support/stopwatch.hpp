// SPDX-License-Identifier: LGPL-2.1-or-later
// Wall time per stage, for timings.json and the benchmark (bench/run.py): a stage's time is
// the time since the previous lap, so consecutive laps cover a run without gaps.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace sliceform {

struct StageTime {
  std::string stage;
  double ms = 0;
  bool alongside = false;  // ran on another thread beside the others: not part of the total
};

class Stopwatch {
 public:
  explicit Stopwatch(std::vector<StageTime>& out) : out_(out) {}
  void lap(const char* stage) {
    const auto now = std::chrono::steady_clock::now();
    out_.push_back({stage, std::chrono::duration<double, std::milli>(now - last_).count()});
    last_ = now;
  }

 private:
  std::vector<StageTime>& out_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace sliceform
