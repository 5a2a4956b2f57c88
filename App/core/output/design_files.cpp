// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/design_files.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <unistd.h>

#include "assembly/fold.hpp"
#include "output/assembly_png.hpp"
#include "output/gltf.hpp"
#include "output/instructions.hpp"
#include "output/report_json.hpp"
#include "output/sheet_dxf.hpp"
#include "output/sheets_cairo.hpp"
#include "support/error.hpp"
#include "support/free_memory.hpp"
#include "support/parallel.hpp"

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
  // The run failed after start(): what an earlier run wrote stays as it was. The STEP file
  // went to a name of its own, which goes, and so does the folder if this run made it.
  discard();
}

void DesignFilesWriter::discard() {
  if (!step_.valid()) return;
  step_.wait();
  step_ = {};
  std::error_code ignored;
  fs::remove(stepFile_, ignored);
  if (madeFolder_) fs::remove(folder_, ignored);  // only if empty
}

void DesignFilesWriter::start(const Design& d) {
  const Vec3 &u = d.arrangement.params.u, &v = d.arrangement.params.v;
  if (step_.valid() && u == begunU_ && v == begunV_) return;
  discard();
  begunU_ = u, begunV_ = v;
  // The design's transient memory (the slot search's caches) is freed by now: back to the
  // system before the STEP writer and the other files ask for theirs (support/free_memory).
  releaseFreeMemory();
  // Posed here, synchronously: the thread then holds its own handles to the faces and
  // nothing of `d`, which the caller goes on to change and move. The BREP file reuses it.
  assembly_ = assemble(d.arrangement, d.patches, foldAngle_);
  // Under a name of its own until finish() renames it: the run may still fail (a patch too
  // large for the sheet), and then the earlier run's assembly.step must stay.
  stepFile_ = (fs::path(folder_) / (".assembly-" + std::to_string(::getpid()) + ".step")).string();
  madeFolder_ = !fs::exists(folder_);
  step_ = std::async(std::launch::async, [assembly = assembly_, file = stepFile_, folder = folder_,
                                          ids = assembledIds(d.arrangement, d.patches)] {
    const auto begin = std::chrono::steady_clock::now();
    createFolder(folder);
    writeShape(assembly, file, ids);
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
  const std::vector<SheetDrawing> sheets = sheetDrawings(d.layout);
  const std::vector<Panel3> panels = assemblyPanels(d.arrangement, d.patches, foldAngle_);
  clock.lap("export drawings");
  // The finished sliceform, drawn once on every core (in bands of rows) before the files:
  // assembly.png and the booklet's cover both show it.
  const Picture picture = drawAssembly(panels);
  clock.lap("export assembly picture");
  // The files are independent of each other: written on all cores, the longest first.
  // (cairo numbers the surfaces of the whole process from one counter; the SVG files,
  // which would carry that number, renumber theirs from 1.)
  struct File {
    const char* stage;
    std::function<void()> write;
  };
  std::vector<File> work{
      {"export booklet, in parallel",
       [&, booklet = path("instructions.pdf")] {
         writeInstructionsPdf(d, panels, picture, fs::path(model.source).filename().string(), booklet);
       }},
      {"export sheets PDF, in parallel",
       [&, pdf = path("sheets.pdf")] { writeSheetsPdf(sheets, d.layout.sheet, pdf); }},
      {"export sheets PNG, in parallel",
       [&, png = path("sheets.png")] { writeSheetsPng(sheets, d.layout.sheet, png); }},
      {"export glTF, in parallel", [&, to = path("assembly.glb")] { writeGltf(panels, to); }},
      {"export assembly PNG, in parallel", [&, to = path("assembly.png")] { writePicturePng(picture, to); }},
      {"export BREP, in parallel", [&, to = path("assembly.brep")] { writeShape(assembly_, to); }},
      {"export report, in parallel",
       [&, to = path("report.json")] { writeJson(reportJson(model, params, d), to); }},
  };
  for (size_t k = 0; k < sheets.size(); ++k) {
    work.push_back({"export SVG, in parallel", [&, k, to = path(sheetFileName(static_cast<int>(k), ".svg"))] {
                      writeSheetSvg(sheets[k], d.layout.sheet, to);
                    }});
    work.push_back({"export DXF, in parallel", [&, k, to = path(sheetFileName(static_cast<int>(k), ".dxf"))] {
                      writeSheetDxf(sheets[k], d.layout.sheet, to);
                    }});
  }
  std::vector<double> ms(work.size());
  parallelFor(work.size(), [&](size_t k) {
    const auto begin = std::chrono::steady_clock::now();
    work[k].write();
    ms[k] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
  });
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
  clock.lap("export files");
  // Each file's own time, summed per kind (the DXF sheets together).
  std::vector<StageTime> own;
  for (size_t k = 0; k < work.size(); ++k) {
    auto same =
        std::find_if(own.begin(), own.end(), [&](const StageTime& t) { return t.stage == work[k].stage; });
    if (same == own.end()) own.push_back({work[k].stage, 0, /*alongside=*/true}), same = own.end() - 1;
    same->ms += ms[k];
  }
  const double stepMs = step_.get();
  const std::string step = path("assembly.step");
  fs::rename(stepFile_, step, failed);
  if (failed) {
    std::error_code ignored;
    fs::remove(stepFile_, ignored);
    throw Error(ErrorKind::Io, "cannot write " + step + ": " + failed.message());
  }
  clock.lap("export STEP, waiting for it");
  timings.insert(timings.end(), own.begin(), own.end());
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
