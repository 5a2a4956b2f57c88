// SPDX-License-Identifier: LGPL-2.1-or-later
// `sliceform slice MODEL`: cuts the model along U and V, writes each slice set as an SVG
// sheet (mm) and prints every slice's area, from the mesh slicer and, for CAD sources,
// from the exact OCCT sections.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "model/model.hpp"
#include "output/slice_svg.hpp"
#include "slicing/brep_slicer.hpp"
#include "slicing/mesh_slicer.hpp"
#include "support/error.hpp"

namespace sliceform::cli {
namespace {

struct SliceOptions : ModelOptions {
  std::string outDir = "slices";
  int slices = 16;
  std::string method = "auto";
};

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void runSlice(const SliceOptions& o) {
  const Model model = readModel(o.model, o.fillHoles);
  requireClosed(model);
  const Vec3 u = o.uDirection(), v = o.vDirection(), w = cross(u, v);
  if (!(norm(w) > 0)) throw Error(ErrorKind::BadParameter, "--u and --v must not be parallel");
  const bool wantExact =
      o.method == "exact" || o.method == "both" || (o.method == "auto" && model.kind == SourceKind::Brep);
  const bool wantMesh =
      o.method == "mesh" || o.method == "both" || (o.method == "auto" && model.kind == SourceKind::Mesh);
  if (wantExact && model.kind != SourceKind::Brep)
    throw Error(ErrorKind::BadParameter, "--method exact needs a CAD model (STEP, IGES or BREP)");

  std::filesystem::create_directories(o.outDir);
  std::printf("model %s: %s, %zu triangles, box %.3f x %.3f x %.3f mm\n", model.source.c_str(),
              model.kind == SourceKind::Brep ? "CAD solid" : "mesh", model.mesh.triangles.size(),
              model.bounds.size().x, model.bounds.size().y, model.bounds.size().z);

  const struct {
    const char* name;
    Vec3 normal;
  } families[] = {{"U", u}, {"V", v}};
  for (const auto& family : families) {
    const SliceFrame frame = makeSliceFrame(family.normal, w);
    const std::vector<double> positions = slicePositions(model.mesh, frame, o.slices);

    SliceSet meshSet, exactSet;
    std::vector<ExactSlice> exact;
    double meshMs = 0, exactMs = 0;
    if (wantMesh) {
      const auto start = std::chrono::steady_clock::now();
      meshSet = sliceMesh(model.mesh, frame, positions);
      meshMs = msSince(start);
    }
    if (wantExact) {
      const auto start = std::chrono::steady_clock::now();
      exact = sliceBrep(model.shape, frame, positions, exactDeflection(model.meshDeflection));
      exactMs = msSince(start);
      exactSet.frame = frame;
      exactSet.interval = positions.size() > 1 ? positions[1] - positions[0] : 0;
      for (const ExactSlice& s : exact) exactSet.slices.push_back({s.position, s.region});
    }

    std::printf("\n%s slices along (%g, %g, %g):\n  #   position mm", family.name, frame.normal.x,
                frame.normal.y, frame.normal.z);
    if (wantMesh) std::printf("   mesh area mm2");
    if (wantExact) std::printf("  exact area mm2");
    std::printf("\n");
    for (size_t i = 0; i < positions.size(); ++i) {
      std::printf("%3zu %13.4f", i, positions[i]);
      if (wantMesh) std::printf(" %16.4f", meshSet.slices[i].region.area());
      if (wantExact) std::printf(" %16.4f", exact[i].area);
      std::printf("\n");
    }
    const double n = static_cast<double>(positions.size());
    if (wantMesh) std::printf("  mesh slicer: %.3f ms per slice\n", meshMs / n);
    if (wantExact) std::printf("  exact slicer: %.3f ms per slice\n", exactMs / n);

    const std::string file = o.outDir + "/slices_" + family.name + ".svg";
    const SliceSet& shown = wantExact ? exactSet : meshSet;
    writeSliceSetSvg(
        shown,
        std::string(family.name) + " slices of " + std::filesystem::path(model.source).filename().string(),
        file);
    std::printf("  wrote %s\n", file.c_str());
  }
}

}  // namespace

Run addSliceCommand(CLI::App& app) {
  auto options = std::make_shared<SliceOptions>();
  CLI::App* cmd =
      app.add_subcommand("slice", "Cut the model along U and V and write the slice sets as SVG (mm).");
  addModelOptions(cmd, *options);
  cmd->add_option("-o,--output", options->outDir, "folder for slices_U.svg and slices_V.svg")
      ->capture_default_str();
  cmd->add_option("-n,--slices", options->slices, "slices per direction")
      ->capture_default_str()
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--method", options->method, "auto (exact for CAD, mesh for meshes), mesh, exact or both")
      ->check(CLI::IsMember({"auto", "mesh", "exact", "both"}))
      ->capture_default_str();
  return [options] { runSlice(*options); };
}

}  // namespace sliceform::cli
