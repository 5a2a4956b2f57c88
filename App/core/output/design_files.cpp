// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/design_files.hpp"

#include <filesystem>
#include <future>

#include "assembly/fold.hpp"
#include "output/assembly_png.hpp"
#include "output/gltf.hpp"
#include "output/report_json.hpp"
#include "output/sheet_dxf.hpp"
#include "output/sheets_cairo.hpp"
#include "support/error.hpp"
#include "support/stopwatch.hpp"

namespace sliceform {

std::string sheetFileName(int sheet, const char* extension) {
  return "sheet-" + std::to_string(sheet + 1) + extension;
}

DesignFiles writeDesignFiles(const Model& model, const DesignParams& params, const Design& d,
                             const std::string& folder, double foldAngle,
                             const std::vector<StageTime>& before) {
  namespace fs = std::filesystem;
  std::error_code failed;
  fs::create_directories(folder, failed);
  if (failed) throw Error(ErrorKind::Io, "cannot create the folder " + folder + ": " + failed.message());
  const fs::path dir(folder);
  DesignFiles files;
  auto path = [&](const std::string& name) {
    files.written.push_back(name);
    return (dir / name).string();
  };
  // timings.json goes last so it can hold what writing the others cost.
  std::vector<StageTime> timings = before;
  timings.insert(timings.end(), d.timings.begin(), d.timings.end());
  Stopwatch clock(timings);
  // The STEP writer is the slowest file and single-threaded (seconds on a mesh's polygon
  // patches), so it runs on the second core while the others are written. It reads the
  // assembly and works on its own copy; nothing else here changes the assembly's shapes
  // (the glTF writer meshes a copy too).
  const TopoDS_Shape assembly = assemble(d.arrangement, d.patches, foldAngle);
  clock.lap("export fold");
  double stepMs = 0;
  std::future<void> step = std::async(std::launch::async, [&, file = path("assembly.step")] {
    std::vector<StageTime> own;
    Stopwatch stepClock(own);
    writeShape(assembly, file);
    stepClock.lap("STEP");
    stepMs = own.front().ms;
  });
  writeJson(reportJson(model, params, d), path("report.json"));
  clock.lap("export report");
  const std::vector<SheetDrawing> sheets = sheetDrawings(d.layout);
  writeSheetsPdf(sheets, d.layout.sheet, path("sheets.pdf"));
  clock.lap("export PDF");
  writeSheetsPng(sheets, d.layout.sheet, path("sheets.png"));
  clock.lap("export sheets PNG");
  for (size_t k = 0; k < sheets.size(); ++k) {
    writeSheetSvg(sheets[k], d.layout.sheet, path(sheetFileName(static_cast<int>(k), ".svg")));
    writeSheetDxf(sheets[k], d.layout.sheet, path(sheetFileName(static_cast<int>(k), ".dxf")));
  }
  for (const char* extension : {".svg", ".dxf"})
    for (int k = static_cast<int>(sheets.size());; ++k) {
      const fs::path stale = dir / sheetFileName(k, extension);
      if (!fs::is_regular_file(stale)) break;
      fs::remove(stale, failed);
      if (failed)
        throw Error(ErrorKind::Io, "cannot remove the stale " + stale.string() + ": " + failed.message());
      files.removed.push_back(stale.filename().string());
    }
  clock.lap("export SVG + DXF");
  writeShape(assembly, path("assembly.brep"));
  clock.lap("export BREP");
  const std::vector<Panel3> panels = assemblyPanels(d.arrangement, d.patches, foldAngle);
  writeGltf(panels, path("assembly.glb"));
  clock.lap("export glTF");
  writeAssemblyPng(panels, path("assembly.png"));
  clock.lap("export assembly PNG");
  step.get();
  clock.lap("export STEP, waiting for it");
  timings.push_back({"export STEP, in parallel", stepMs, /*alongside=*/true});
  writeJson(timingsJson(timings), path("timings.json"));
  return files;
}

}  // namespace sliceform
