// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/sheet_dxf.hpp"

#include <dl_dxf.h>
#include <dl_exception.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>

#include "support/atomic_file.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

const char* const kCutLayer = "CUT";
const char* const kEngraveLayer = "ENGRAVE";
constexpr int kRed = 1, kBlue = 5, kWhite = 7;  // AutoCAD colour index
constexpr int kMillimetres = 4;                 // $INSUNITS
constexpr int kMetric = 1;                      // $MEASUREMENT

// dxflib's own writer formats every number with sprintf("%.16f") and flushes the file after
// each one: ChineseDragon's 11 sheets took 353 ms of thread time, 5 % of the run's CPU, most
// of it in write calls. This one writes the very same text (std::to_chars gives printf's
// digits, in any locale) through a buffer of its own, to the file a megabyte at a time. Its
// base opens the file too, as dxflib's writer does, and writes nothing: every write of
// dxflib's goes through these (dxfBool through dxfInt, handles through dxfHex).
class BufferedWriter final : public DL_WriterA {
 public:
  BufferedWriter(const char* file, DL_Codes::version version)
      : DL_WriterA(file, version), out_(file, std::ios::binary | std::ios::trunc) {}

  void dxfReal(int gc, double value) const override {
    char text[512];
    // Room for any double: 309 digits, the point, 16 decimals and a sign.
    char* end = std::to_chars(text, text + sizeof text - 1, value, std::chars_format::fixed, 16).ptr;
    *end = '\0';
    // As dxflib does: trailing zeros cut, one digit after the point kept.
    const char* dot = std::strchr(text, '.');
    if (dot) {
      char* keep = text + (dot - text) + 2;
      for (char* c = keep; c < end; ++c)
        if (*c != '0') keep = c + 1;
      if (keep < end) *keep = '\0';
    }
    put(gc, text);
  }
  void dxfInt(int gc, int value) const override { put(gc, std::to_string(value).c_str()); }
  void dxfHex(int gc, int value) const override {
    char text[12];
    std::snprintf(text, sizeof text, "%0X", value);
    put(gc, text);
  }
  void dxfString(int gc, const char* value) const override {
    if (!value) throw DL_NullStrExc();
    put(gc, value);
  }
  void dxfString(int gc, const std::string& value) const override { put(gc, value.c_str()); }

  bool openFailed() const { return !out_ || DL_WriterA::openFailed(); }

  // Writes what is left; false when any write failed.
  bool finish() const {
    flush();
    out_.close();
    close();
    return static_cast<bool>(out_);
  }

 private:
  static constexpr size_t kChunk = size_t{1} << 20;
  void put(int gc, const char* value) const {
    text_ += gc < 10 ? "  " : gc < 100 ? " " : "";
    text_ += std::to_string(gc);
    text_ += '\n';
    text_ += value;
    text_ += '\n';
    if (text_.size() >= kChunk) flush();
  }
  void flush() const {
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }
  mutable std::ofstream out_;
  mutable std::string text_;
};

// Entities carry their layer's colour as well (not BYLAYER): some laser software tells cut
// from engrave by the entity's own colour and ignores layers.
DL_Attributes onLayer(const char* layer, int colour) {
  return DL_Attributes(layer, colour, -1, "BYLAYER", 1.0);
}

// dxflib numbers handles from 0x30 on; its tables and objects take fewer than 0x100 of them
// and every entity one more. $HANDSEED must exceed them all, and the 0xFFFF that dxflib's
// own header writes does not for a sheet of more than 65000 entities (meshes give many lines).
int handleSeed(const SheetDrawing& drawing) {
  size_t entities = drawing.engrave.size();
  for (const CutLoop& loop : drawing.cut) entities += loop.size();
  return static_cast<int>(std::max<size_t>(0xFFFF, 0x30 + 0x100 + entities));
}

// Written here rather than by DL_Dxf::writeHeader, which fixes $HANDSEED and stops after it.
void writeHeader(DL_WriterA& dw, const SheetDrawing& drawing, const SheetSpec& sheet) {
  dw.sectionHeader();
  dw.dxfString(9, "$ACADVER");
  dw.dxfString(1, "AC1015");
  dw.dxfString(9, "$HANDSEED");
  dw.dxfHex(5, handleSeed(drawing));
  dw.dxfString(9, "$INSUNITS");
  dw.dxfInt(70, kMillimetres);
  dw.dxfString(9, "$MEASUREMENT");
  dw.dxfInt(70, kMetric);
  // The drawing limits are the sheet, so a CAD program shows where the paper ends.
  dw.dxfString(9, "$LIMMIN");
  dw.dxfReal(10, 0.0);
  dw.dxfReal(20, 0.0);
  dw.dxfString(9, "$LIMMAX");
  dw.dxfReal(10, sheet.width);
  dw.dxfReal(20, sheet.height);
  dw.sectionEnd();
}

void writeLinetypes(DL_Dxf& dxf, DL_WriterA& dw) {
  dw.tableLinetypes(3);
  for (const char* name : {"BYBLOCK", "BYLAYER", "CONTINUOUS"})
    dxf.writeLinetype(dw, DL_LinetypeData(name, "", 0, 0, 0.0));
  dw.tableEnd();
}

void writeLayers(DL_Dxf& dxf, DL_WriterA& dw) {
  dw.tableLayers(3);
  dxf.writeLayer(dw, DL_LayerData("0", 0), DL_Attributes("", kWhite, -1, "CONTINUOUS", 1.0));
  dxf.writeLayer(dw, DL_LayerData(kCutLayer, 0), DL_Attributes("", kRed, -1, "CONTINUOUS", 1.0));
  dxf.writeLayer(dw, DL_LayerData(kEngraveLayer, 0), DL_Attributes("", kBlue, -1, "CONTINUOUS", 1.0));
  dw.tableEnd();
}

// Every table an R2000 reader (AutoCAD above all) insists on, in the order dxflib's
// documentation gives; only the layers and line types say anything about the sheet.
void writeTables(DL_Dxf& dxf, DL_WriterA& dw) {
  dw.sectionTables();
  dxf.writeVPort(dw);
  writeLinetypes(dxf, dw);
  writeLayers(dxf, dw);
  dw.tableStyle(1);
  dxf.writeStyle(dw, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
  dw.tableEnd();
  dxf.writeView(dw);
  dxf.writeUcs(dw);
  dw.tableAppid(1);
  dxf.writeAppid(dw, "ACAD");
  dw.tableEnd();
  dxf.writeDimStyle(dw, 2.5, 1.25, 0.625, 0.625, 2.5);
  dxf.writeBlockRecord(dw);
  dw.tableEnd();
  dw.sectionEnd();
}

// The model and paper space blocks R2000 requires, empty: the entities follow in ENTITIES.
void writeBlocks(DL_Dxf& dxf, DL_WriterA& dw) {
  dw.sectionBlocks();
  for (const char* name : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
    dxf.writeBlock(dw, DL_BlockData(name, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(dw, name);
  }
  dw.sectionEnd();
}

// DXF angles are degrees in [0, 360).
double degrees(double radians) {
  const double d = std::fmod(radians * 180 / M_PI, 360.0);
  return d < 0 ? d + 360 : d;
}

void writeElement(DL_Dxf& dxf, DL_WriterA& dw, const CutElement& e, const DL_Attributes& cut) {
  switch (e.kind) {
    case CutElement::Kind::Line:
      dxf.writeLine(dw, DL_LineData(e.a.x, e.a.y, 0.0, e.b.x, e.b.y, 0.0), cut);
      break;
    case CutElement::Kind::Arc: {
      // A DXF arc always runs counter-clockwise from angle 1 to angle 2, so a clockwise arc is
      // written as the same points from its end to its start.
      const double from = e.ccw ? e.start : e.end, to = e.ccw ? e.end : e.start;
      dxf.writeArc(dw, DL_ArcData(e.centre.x, e.centre.y, 0.0, e.radius, degrees(from), degrees(to)), cut);
      break;
    }
    case CutElement::Kind::Circle:
      dxf.writeCircle(dw, DL_CircleData(e.centre.x, e.centre.y, 0.0, e.radius), cut);
      break;
  }
}

// One polyline per stroke: the engraver follows it without lifting, and it costs one
// entity instead of one per segment.
void writeStroke(DL_Dxf& dxf, DL_WriterA& dw, const Stroke& stroke, const DL_Attributes& engrave) {
  if (stroke.size() < 2) return;
  dxf.writePolyline(dw, DL_PolylineData(static_cast<int>(stroke.size()), 0, 0, 0), engrave);
  for (const Vec2& p : stroke) dxf.writeVertex(dw, DL_VertexData(p.x, p.y));
  dxf.writePolylineEnd(dw);
}

void writeEntities(DL_Dxf& dxf, DL_WriterA& dw, const SheetDrawing& drawing) {
  const DL_Attributes cut = onLayer(kCutLayer, kRed), engrave = onLayer(kEngraveLayer, kBlue);
  dw.sectionEntities();
  for (const CutLoop& loop : drawing.cut)
    for (const CutElement& e : loop) writeElement(dxf, dw, e, cut);
  for (const Stroke& s : drawing.engrave) writeStroke(dxf, dw, s, engrave);
  dw.sectionEnd();
}

// dxflib reports no write errors (a full disk, say); a file that ends in EOF was written whole.
bool writtenWhole(const std::string& file) {
  const std::string tail = "EOF\n";
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in || in.tellg() < static_cast<std::streamoff>(tail.size())) return false;
  in.seekg(-static_cast<std::streamoff>(tail.size()), std::ios::end);
  std::string got(tail.size(), '\0');
  in.read(got.data(), static_cast<std::streamsize>(got.size()));
  return in && got == tail;
}

void writeFile(const SheetDrawing& drawing, const SheetSpec& sheet, const std::string& file,
               const std::string& path) {
  DL_Dxf dxf;
  // out() sets the version DL_Dxf's entity writers follow (it has no setter, and its default
  // is not documented); the writer it makes is dropped for ours.
  if (!std::unique_ptr<DL_WriterA>(dxf.out(file.c_str(), DL_Codes::AC1015)))
    throw Error(ErrorKind::Io, "cannot write " + path);
  BufferedWriter dw(file.c_str(), DL_Codes::AC1015);
  if (dw.openFailed()) throw Error(ErrorKind::Io, "cannot write " + path);
  writeHeader(dw, drawing, sheet);
  writeTables(dxf, dw);
  writeBlocks(dxf, dw);
  writeEntities(dxf, dw, drawing);
  dxf.writeObjects(dw);
  dxf.writeObjectsEnd(dw);
  dw.dxfEOF();
  if (!dw.finish() || !writtenWhole(file)) throw Error(ErrorKind::Io, "cannot write " + path);
}

}  // namespace

void writeSheetDxf(const SheetDrawing& drawing, const SheetSpec& sheet, const std::string& path) {
  writeAtomically(path, [&](const std::string& file) { writeFile(drawing, sheet, file, path); });
}

}  // namespace sliceform
