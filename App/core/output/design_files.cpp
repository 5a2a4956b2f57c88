// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/design_files.hpp"

#include <chrono>
#include <filesystem>

#include <unistd.h>

#include "assembly/fold.hpp"
#include "output/assembly_png.hpp"
#include "output/gltf.hpp"
#include "output/report_json.hpp"
#include "output/sheet_dxf.hpp"
#include "output/sheets_cairo.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

namespace fs = std::filesystem;

void createFolder(const std::string& folder) {
  std::error_code failed;
  fs::create_directories(folder, failed);
  if (failed) throw Error(ErrorKind::Io, "cannot create the folder " + folder + ": " + failed.message());
}

}  // namespace

std::string sheetFileName(int sheet, const char* extension) {
  return "sheet-" + std::to_string(sheet + 1) + extension;
}

DesignFilesWriter::DesignFilesWriter(std::string folder, double foldAngleDegrees)
    : folder_(std::move(folder)), foldAngle_(foldAngleDegrees) {}

DesignFilesWriter::~DesignFilesWriter() {
  if (!step_.valid()) return;
  // The run failed after start(): what an earlier run wrote stays as it was. The STEP file
  // went to a name of its own, which goes, and so does the folder if this run made it.
  step_.wait();
  std::error_code ignored;
  fs::remove(stepFile_, ignored);
  if (madeFolder_) fs::remove(folder_, ignored);  // only if empty
}

void DesignFilesWriter::start(const Design& d) {
  if (step_.valid()) return;
  // Posed here, synchronously: the thread then holds its own handles to the faces and
  // nothing of `d`, which the caller goes on to change and move.
  TopoDS_Shape assembly = assemble(d.arrangement, d.patches, foldAngle_);
  // Under a name of its own until finish() renames it: the run may still fail (a patch too
  // large for the sheet), and then the earlier run's assembly.step must stay.
  stepFile_ = (fs::path(folder_) / (".assembly-" + std::to_string(::getpid()) + ".step")).string();
  madeFolder_ = !fs::exists(folder_);
  step_ =
      std::async(std::launch::async, [assembly = std::move(assembly), file = stepFile_, folder = folder_] {
        const auto begin = std::chrono::steady_clock::now();
        createFolder(folder);
        writeShape(assembly, file);
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
      });
}

DesignFiles DesignFilesWriter::finish(const Model& model, const DesignParams& params, const Design& d,
                                      const std::vector<StageTime>& before) {
  createFolder(folder_);
  start(d);
  const fs::path dir(folder_);
  DesignFiles files;
  auto path = [&](const std::string& name) {
    files.written.push_back(name);
    return (dir / name).string();
  };
  // timings.json goes last so it can hold what writing the others cost.
  std::vector<StageTime> timings = before;
  timings.insert(timings.end(), d.timings.begin(), d.timings.end());
  Stopwatch clock(timings);
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
  std::error_code failed;
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
  writeShape(assemble(d.arrangement, d.patches, foldAngle_), path("assembly.brep"));
  clock.lap("export BREP");
  const std::vector<Panel3> panels = assemblyPanels(d.arrangement, d.patches, foldAngle_);
  writeGltf(panels, path("assembly.glb"));
  clock.lap("export glTF");
  writeAssemblyPng(panels, path("assembly.png"));
  clock.lap("export assembly PNG");
  const double stepMs = step_.get();
  const std::string step = path("assembly.step");
  fs::rename(stepFile_, step, failed);
  if (failed) {
    std::error_code ignored;
    fs::remove(stepFile_, ignored);
    throw Error(ErrorKind::Io, "cannot write " + step + ": " + failed.message());
  }
  clock.lap("export STEP, waiting for it");
  timings.push_back({"export STEP, in parallel", stepMs, /*alongside=*/true});
  writeJson(timingsJson(timings), path("timings.json"));
  return files;
}

DesignFiles writeDesignFiles(const Model& model, const DesignParams& params, const Design& d,
                             const std::string& folder, double foldAngle,
                             const std::vector<StageTime>& before) {
  DesignFilesWriter writer(folder, foldAngle);
  return writer.finish(model, params, d, before);
}

}  // namespace sliceform
