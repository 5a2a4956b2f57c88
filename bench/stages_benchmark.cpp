// SPDX-License-Identifier: LGPL-2.1-or-later
// Google Benchmark of the core stages (issue 7), in process so that start-up, reading and
// file output do not blur them: the mesh slicer (2 x 128 slices), the exact OCCT slicer per
// slice (issue target: <= 2 ms a slice) on every OCCT CAD part that designs, by section
// curves and by the Boolean Common, the exact-patch stage alone, and runDesign end to end at
// 64 and 128 slices.
// Models come from occt-misc (SLICEFORM_BENCH_MESH / SLICEFORM_BENCH_CAD override them) and
// an OCCT-built bracket, all scaled to 150 mm like `sliceform design --size 150`.
#include <benchmark/benchmark.h>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "exact/patch_faces.hpp"
#include "model/model.hpp"
#include "pipeline/design.hpp"
#include "slicing/brep_slicer.hpp"
#include "slicing/mesh_slicer.hpp"

namespace sf = sliceform;

namespace {

std::string path(const char* env, const char* fallback) {
  const char* p = std::getenv(env);
  return p ? p : fallback;
}

// Read once per process: reading is not a stage measured here.
const sf::Model* model(const std::string& which) {
  static std::map<std::string, sf::Model> cache;
  auto it = cache.find(which);
  if (it != cache.end()) return &it->second;
  sf::Model m;
  if (which == "bracket") {  // a plate with a through hole: planes, a cylinder, their seams
    const TopoDS_Shape plate = BRepPrimAPI_MakeBox(60, 40, 20).Shape();
    const TopoDS_Shape hole =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, -1), gp_Dir(0, 0, 1)), 10, 22).Shape();
    m = sf::modelFromShape(BRepAlgoAPI_Cut(plate, hole).Shape(), "bracket");
  } else {
    if (!std::filesystem::exists(which)) return nullptr;
    m = sf::readModel(which);
  }
  return &cache.emplace(which, sf::scaledToSize(m, 150)).first->second;
}

const std::string kMesh = path("SLICEFORM_BENCH_MESH", "/usr/share/opencascade/data/stl/sh1.stl");
const std::string kCad = path("SLICEFORM_BENCH_CAD", "/usr/share/opencascade/data/step/screw.step");

// Both families, as the pipeline cuts them: U = X, V = Y, W = Z up.
const sf::SliceFrame kFrames[2] = {sf::makeSliceFrame({1, 0, 0}, {0, 0, 1}),
                                   sf::makeSliceFrame({0, 1, 0}, {0, 0, 1})};

void BM_sliceMesh(benchmark::State& state) {
  const sf::Model* m = model(kMesh);
  if (!m) return state.SkipWithError(("missing " + kMesh).c_str());
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state)
    for (const sf::SliceFrame& f : kFrames)
      benchmark::DoNotOptimize(sf::sliceMesh(m->mesh, f, sf::slicePositions(m->mesh, f, n)));
  state.SetLabel(std::to_string(m->mesh.triangles.size()) + " triangles");
}

// ms per slice is the figure the issue sets a target for; counted over both families. The
// sections are the faces (what the exact patches use); "measured" adds the adaptive area
// integration and the polygons that `sliceform slice --method exact` reports.
void sliceBrepBench(benchmark::State& state, const std::string& which, sf::SliceDetail detail,
                    sf::SectionRoute route = sf::SectionRoute::FaceByFace) {
  const sf::Model* m = model(which);
  if (!m) return state.SkipWithError(("missing " + which).c_str());
  const int n = static_cast<int>(state.range(0));
  double ms = 0;
  int made = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    made = 0;
    for (const sf::SliceFrame& f : kFrames)
      for (const sf::ExactSlice& s : sf::sliceBrep(m->shape, f, sf::slicePositions(m->mesh, f, n),
                                                   sf::exactDeflection(m->meshDeflection), detail, route))
        made += s.route == route;
    ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  state.counters["ms_per_slice"] = ms / (static_cast<double>(state.iterations()) * 2 * n);
  // The share of planes the route asked for made itself (the rest fell back).
  state.counters["own_share"] = made / (2.0 * n);
}
void BM_sliceBrep_cad(benchmark::State& state) {
  sliceBrepBench(state, kCad, sf::SliceDetail::FacesOnly);
}
void BM_sliceBrep_cad_measured(benchmark::State& state) {
  sliceBrepBench(state, kCad, sf::SliceDetail::Measured);
}
void BM_sliceBrep_bracket(benchmark::State& state) {
  sliceBrepBench(state, "bracket", sf::SliceDetail::FacesOnly);
}

// The design the exact patches are built for, made once per process.
const sf::Design* designOf(const std::string& which) {
  static std::map<std::string, sf::Design> cache;
  auto it = cache.find(which);
  if (it != cache.end()) return &it->second;
  const sf::Model* m = model(which);
  if (!m) return nullptr;
  sf::DesignParams params;
  params.arrangement.slices = 128;
  return &cache.emplace(which, sf::runDesign(*m, params)).first->second;
}

// The exact-patch stage alone (sections of every slice the patches need, the fused
// cylinder sections, the slots), ms per patch.
void exactPatchesBench(benchmark::State& state, const std::string& which) {
  const sf::Design* d = designOf(which);
  if (!d) return state.SkipWithError(("missing " + which).c_str());
  double ms = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(sf::exactPatches(*model(which), d->arrangement, d->realization));
    ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  const double patches = static_cast<double>(d->arrangement.scaffold.patches.size());
  state.counters["patches"] = patches;
  state.counters["ms_per_patch"] = ms / (static_cast<double>(state.iterations()) * patches);
}

// Every part of /usr/share/opencascade/data with exact sections that `bench/sweep.py --occt`
// designs (SLICEFORM_BENCH_PARTS, a colon-separated list, overrides it): the target
// is the median of their ms per slice.
std::vector<std::string> cadParts() {
  const std::string data = "/usr/share/opencascade/data/";
  std::string list = path("SLICEFORM_BENCH_PARTS", "");
  std::vector<std::string> out;
  if (list.empty())
    for (const char* p :
         {"occ/Axis_of_bearing.brep", "occ/Ball.brep", "occ/Bottom.brep", "occ/CrankArm.brep",
          "occ/MODERN_Chair_1.brep", "occ/MODERN_Cooker_1.brep", "occ/MODERN_MVCooker_1.brep",
          "occ/MODERN_MVCooker_1_opened.brep", "occ/MODERN_Sink_1.brep", "occ/Pump_Nut.brep",
          "occ/Pump_TopCover.brep", "occ/fuse.brep", "occ/mal_ecrou.brep", "occ/mal_tige.brep",
          "occ/mal_vis.brep", "occ/solid.brep", "occ/wedge_ok.brep", "step/linkrods.step", "step/screw.step"})
      out.push_back(data + p);
  std::istringstream in(list);
  for (std::string p; std::getline(in, p, ':');)
    if (!p.empty()) out.push_back(p);
  return out;
}

void designBench(benchmark::State& state, const std::string& which) {
  const sf::Model* m = model(which);
  if (!m) return state.SkipWithError(("missing " + which).c_str());
  sf::DesignParams params;
  params.arrangement.slices = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(sf::runDesign(*m, params));
}
void BM_runDesign_mesh(benchmark::State& state) {
  designBench(state, kMesh);
}
void BM_runDesign_cad(benchmark::State& state) {
  designBench(state, kCad);
}

}  // namespace

// Wall time: the slicers and the pipeline use every core. The slow ones run a fixed three
// times (median reported) instead of Google Benchmark's calibrated count.
BENCHMARK(BM_sliceMesh)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime();
// Whole-stage runs take seconds: one iteration each, three repetitions, their median.
// The per-part rows: one run each (19 parts, two routes; the Boolean route takes up to
// 30 s on a part).
void once(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
}
void slow(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true);
}
BENCHMARK(BM_sliceBrep_cad)->Arg(128)->Apply(slow);
BENCHMARK(BM_sliceBrep_cad_measured)->Arg(128)->Apply(slow);
BENCHMARK(BM_sliceBrep_bracket)->Arg(128)->Apply(slow);
BENCHMARK(BM_runDesign_mesh)->Arg(64)->Arg(128)->Apply(slow);
BENCHMARK(BM_runDesign_cad)->Arg(64)->Arg(128)->Apply(slow);

int main(int argc, char** argv) {
  for (const std::string& part : cadParts()) {
    const std::string name = std::filesystem::path(part).filename().string();
    benchmark::RegisterBenchmark(("sections/" + name).c_str(),
                                 [part](benchmark::State& s) {
                                   sliceBrepBench(s, part, sf::SliceDetail::FacesOnly,
                                                  sf::SectionRoute::FaceByFace);
                                 })
        ->Arg(128)
        ->Apply(once);
    benchmark::RegisterBenchmark(("sections_curves/" + name).c_str(),
                                 [part](benchmark::State& s) {
                                   sliceBrepBench(s, part, sf::SliceDetail::FacesOnly,
                                                  sf::SectionRoute::Curves);
                                 })
        ->Arg(128)
        ->Apply(once);
    benchmark::RegisterBenchmark(("sections_common/" + name).c_str(),
                                 [part](benchmark::State& s) {
                                   sliceBrepBench(s, part, sf::SliceDetail::FacesOnly,
                                                  sf::SectionRoute::Common);
                                 })
        ->Arg(128)
        ->Apply(once);
    benchmark::RegisterBenchmark(("exactPatches/" + name).c_str(), [part](benchmark::State& s) {
      exactPatchesBench(s, part);
    })->Apply(once);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
