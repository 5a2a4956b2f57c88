// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/design_files.hpp"

#include <filesystem>

#include "assembly/fold.hpp"
#include "output/assembly_png.hpp"
#include "output/gltf.hpp"
#include "output/report_json.hpp"
#include "output/sheet_dxf.hpp"
#include "output/sheets_cairo.hpp"
#include "support/error.hpp"

namespace sliceform {

std::string sheetFileName(int sheet, const char* extension) {
  return "sheet-" + std::to_string(sheet + 1) + extension;
}

DesignFiles writeDesignFiles(const Model& model, const DesignParams& params, const Design& d,
                             const std::string& folder, double foldAngle) {
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
  writeJson(reportJson(model, params, d), path("report.json"));
  writeJson(timingsJson(d), path("timings.json"));
  const std::vector<SheetDrawing> sheets = sheetDrawings(d.layout);
  writeSheetsPdf(sheets, d.layout.sheet, path("sheets.pdf"));
  writeSheetsPng(sheets, d.layout.sheet, path("sheets.png"));
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
  const TopoDS_Shape assembly = assemble(d.arrangement, d.patches, foldAngle);
  writeShape(assembly, path("assembly.step"));
  writeShape(assembly, path("assembly.brep"));
  writeGltf(assembly, path("assembly.glb"), assemblyFamilies(d.arrangement, d.patches));
  writeAssemblyPng(assemblyPanels(d.arrangement, d.patches, foldAngle), path("assembly.png"));
  return files;
}

}  // namespace sliceform
