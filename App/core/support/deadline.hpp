// SPDX-License-Identifier: LGPL-2.1-or-later
// The time a design may take (--time-limit): the searches that could run long (moving
// patches off grazes, the slot search, repairing split patches) look at it between steps
// and stop with the best they have found when it has passed; the exact patches not yet
// cut are then the search's polygons, and no other directions are tried. One deadline
// covers a whole run, every frame designed included. It is a last resort: on every model
// we have, the searches end by themselves in seconds.
#pragma once

#include <atomic>
#include <chrono>

namespace sliceform {

class Deadline {
 public:
  Deadline() = default;  // never passes
  Deadline(const Deadline&) = delete;  // one deadline, shared by reference
  Deadline& operator=(const Deadline&) = delete;
  explicit Deadline(double seconds)
      : end_(std::chrono::steady_clock::now() +
             std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                 std::chrono::duration<double>(seconds))),
        limited_(seconds > 0),
        seconds_(seconds) {}
  bool passed() const {
    if (limited_ && !passed_ && std::chrono::steady_clock::now() >= end_) passed_ = true;
    return passed_;
  }
  double seconds() const { return seconds_; }

 private:
  std::chrono::steady_clock::time_point end_{};
  bool limited_ = false;
  double seconds_ = 0;
  mutable std::atomic<bool> passed_{false};  // once passed, passed: every search stops alike
};

}  // namespace sliceform
