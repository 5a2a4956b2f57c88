// SPDX-License-Identifier: LGPL-2.1-or-later
// parallelFor: runs fn(i) for i in [0, count) on every core. The first exception thrown by
// any call is rethrown on the calling thread, as it was thrown, once all workers have
// stopped; calls not yet started then do not run.
//
// The threads are OCCT's default pool, made once per process (inside FreeCAD, the pool
// FreeCAD's own OCCT algorithms use), not new threads per call. A parallelFor inside
// another one runs on the threads the outer one left free, down to the calling thread
// alone: OSD_ThreadPool::Launcher locks only idle threads, so nesting cannot deadlock.
#pragma once

#include <OSD_ThreadPool.hxx>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>

namespace sliceform {

template <class Fn>
void parallelFor(size_t count, Fn&& fn) {
  std::exception_ptr failure;
  std::mutex failureMutex;
  std::atomic<bool> failed{false};
  const auto one = [&](size_t i) {
    if (failed) return;
    try {
      fn(i);
    } catch (...) {
      // Caught here, not by the pool: OSD_ThreadPool would turn it into a Standard_Failure
      // and lose the core's Error and its kind.
      std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure) failure = std::current_exception();
      failed = true;
    }
  };
  if (count == 1) {
    one(0);
  } else if (count > 1) {
    const Handle(OSD_ThreadPool)& pool = OSD_ThreadPool::DefaultPool();
    OSD_ThreadPool::Launcher launcher(*pool, static_cast<int>(std::min<size_t>(count, pool->NbThreads())));
    launcher.Perform(0, static_cast<int>(count), [&](int, int i) { one(static_cast<size_t>(i)); });
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace sliceform
