// SPDX-License-Identifier: LGPL-2.1-or-later
// What the process frees, kept where it can be used again or handed back to the system
// (glibc; elsewhere these do nothing).
//
// glibc keeps what a thread frees in that thread's arena for that arena's next requests, and
// makes up to 8 arenas a core: a thread started later gets a new one. occ/Top.brep: the slot
// search's caches reach 140 MB in use and are freed by the end of the design (28 MB in use),
// but the arenas keep about 150 MB resident, and the STEP writer's thread, started then,
// took 100 MB more beside them: the run peaked at 261-330 MB (six runs).
#pragma once

#include <OSD_ThreadPool.hxx>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace sliceform {

// Hands the free pages of every arena back to the system. Inside FreeCAD's process too (its
// export): a pass over the free lists, each arena locked while it is trimmed, once an export.
inline void releaseFreeMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

// Two arenas a core, for a process that owns its allocator (the CLI built without mimalloc,
// which replaces glibc's malloc there and needs none of this; not FreeCAD): one for
// each thread that allocates while others do, no more, so that a thread started late
// shares the memory earlier threads freed. The threads: OCCT's pool (parallelFor's, one a
// core with the calling thread), OCCT's TBB threads (BRepMesh, while the model is read),
// and the STEP writer's, which runs beside the layout. With one arena a core the STEP
// writer shared an arena with a pool thread, and both waited on its lock (three runs each:
// MODERN_Cooker_1 5.90 -> 5.46 s, Bottom 5.56 -> 5.18 s, Ball 2.81 -> 2.67 s; peak memory
// Top 217 -> 240 MB, Bottom 193 -> 211 MB, as against 261-330 MB on Top with glibc's eight
// a core). A limit the user set (MALLOC_ARENA_MAX, or glibc's tunables) is left as it is.
//
// The threads of OCCT's pool (parallelFor's) then take their arenas at once, one each. A
// thread takes its arena at its first allocation, and OCCT's TBB threads (BRepMesh, while
// the model is read) allocated before the pool's first job: the pool's thread then shared
// the main thread's arena, and the two waited on its lock in every parallel stage
// (occt-misc Axis_of_bearing.brep: a third of the exact patches' samples in malloc's lock,
// 2.1 s a run, 1.25 s with more arenas).
inline void arenasForWorkingThreads() {
#if defined(__GLIBC__)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (std::getenv("MALLOC_ARENA_MAX") || (tunables && std::strstr(tunables, "arena_max"))) return;
  mallopt(M_ARENA_MAX, 2 * static_cast<int>(std::max(2u, std::thread::hardware_concurrency())));
  const Handle(OSD_ThreadPool)& pool = OSD_ThreadPool::DefaultPool();
  OSD_ThreadPool::Launcher launcher(*pool, pool->NbThreads());
  const int threads = launcher.NbThreads();
  std::atomic<int> started{0};
  // Each of the launcher's threads (the calling one among them) takes one index and waits
  // for the others, so every one of them allocates; a second at most, should one not come.
  launcher.Perform(0, threads, [&](int, int) {
    ++started;
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    while (started < threads && std::chrono::steady_clock::now() < until) std::this_thread::yield();
    void* volatile block = std::malloc(64);
    std::free(block);
  });
#endif
}

}  // namespace sliceform
