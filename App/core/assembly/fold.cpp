// SPDX-License-Identifier: LGPL-2.1-or-later
#include "assembly/fold.hpp"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax1.hxx>

#include <cmath>
#include <fstream>
#include <mutex>
#include <vector>

#include "assembly/polyline_faces.hpp"
#include "assembly/step_text.hpp"
#include "support/atomic_file.hpp"
#include "support/error.hpp"
#include "support/occt_guard.hpp"
#include "support/occt_statics.hpp"
#include "support/plane_curves.hpp"

namespace sliceform {
namespace {

gp_Vec vec(const Vec3& v) {
  return {v.x, v.y, v.z};
}

bool endsWith(const std::string& s, const std::string& tail) {
  if (s.size() < tail.size()) return false;
  std::string end = s.substr(s.size() - tail.size());
  for (char& c : end) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return end == tail;
}

// The patches the assembly holds, in its order: those with a shape.
std::vector<int> assembled(const std::vector<PatchFace>& patches) {
  std::vector<int> out;
  for (size_t k = 0; k < patches.size(); ++k)
    if (!patches[k].shape.IsNull()) out.push_back(static_cast<int>(k));
  return out;
}

}  // namespace

gp_Trsf foldTransform(const Arrangement& a, int patch, double thetaDegrees) {
  if (!(thetaDegrees > 0 && thetaDegrees <= 90))
    throw Error(ErrorKind::BadParameter, "the fold angle must be in (0, 90] degrees");
  const double theta = thetaDegrees * M_PI / 180;
  const ScaffoldPatch& p = a.scaffold.patches[patch];
  const gp_Vec u = vec(a.u.frame.normal), v = vec(a.v.frame.normal), w = vec(a.u.frame.yAxis);
  gp_Trsf t;
  if (p.family == Family::U) {
    t.SetTranslation(u * (p.position * (std::sin(theta) - 1)) + v * (p.position * std::cos(theta)));
  } else {
    const gp_Vec through = v * p.position;
    t.SetRotation(gp_Ax1(gp_Pnt(through.XYZ()), gp_Dir(w)), M_PI / 2 - theta);
  }
  return t;
}

TopoDS_Shape assemble(const Arrangement& a, const std::vector<PatchFace>& patches, double thetaDegrees) {
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (const int k : assembled(patches))
    builder.Add(all, patches[k].shape.Moved(TopLoc_Location(foldTransform(a, k, thetaDegrees))));
  return all;
}

std::vector<std::string> assembledIds(const Arrangement& a, const std::vector<PatchFace>& patches) {
  std::vector<std::string> ids;
  for (const int k : assembled(patches)) ids.push_back(patchId(a.scaffold, k));
  return ids;
}

void writeShape(const TopoDS_Shape& shape, const std::string& path, const std::vector<std::string>& names) {
  const bool step = endsWith(path, ".step") || endsWith(path, ".stp");
  if (!step && !endsWith(path, ".brep"))
    throw Error(ErrorKind::BadParameter, path + ": the 3D assembly is written as .step, .stp or .brep");
  writeAtomically(path, [&](const std::string& temporary) {
    occtGuard("writing the assembly", [&] {
      if (!step) {
        if (!BRepTools::Write(shape, temporary.c_str())) throw Error(ErrorKind::Io, "cannot write " + path);
        return;
      }
      // Our writer takes every edge as it is, a mesh's polygon loops as their straight edges:
      // written as one degree-1 B-spline a loop (polylineLoopsAsSplines, which OCCT's writer
      // needs to be quick), FreeCAD's Face.Area reads such a face up to 9 times its area.
      std::string text;
      if (planarFacesStep(shape, text, names)) {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.close();
        if (!out) throw Error(ErrorKind::Io, "cannot write " + path);
        return;
      }
      // Anything else by OCCT's writer, whose settings are process-wide statics; a mesh's
      // polygon loops go to it as one edge each, its time growing with the edges.
      const TopoDS_Shape polygons = polylineLoopsAsSplines(shape);
      static std::mutex lock;
      std::lock_guard<std::mutex> hold(lock);
      // The writer prints transfer statistics on stdout, which is the CLI's summary.
      const Message_SequenceOfPrinters& printers = Message::DefaultMessenger()->Printers();
      std::vector<Message_Gravity> levels;
      for (int i = 1; i <= printers.Length(); ++i) {
        levels.push_back(printers(i)->GetTraceLevel());
        printers(i)->SetTraceLevel(Message_Fail);
      }
      struct Restore {
        const Message_SequenceOfPrinters& printers;
        std::vector<Message_Gravity>& levels;
        ~Restore() {
          for (int i = 1; i <= printers.Length(); ++i) printers(i)->SetTraceLevel(levels[i - 1]);
        }
      } restore{printers, levels};
      // The planes' 2D curves stored once, not projected again and again while the writer
      // bounds the faces, and trimmed to their edges (withPlaneCurves).
      const TopoDS_Shape withCurves = withPlaneCurves(polygons, true);
      // The writer's settings: AP214, millimetres, and no 2D curves on the planes (readers
      // rebuild them, and they doubled the file and the time: a mesh's polygon patches have
      // tens of thousands of edges). The schema is ours too, not the host's: OCCT 7.8.1
      // crashes writing AP203 (a user's FreeCAD preference). They are process-wide statics,
      // FreeCAD's own STEP/IGES export settings too: every static is put back as it was when
      // the writer is done, also when it fails. The writer's controller is set up first, so
      // its statics are in the snapshot. OCCT 7.8's writer also takes its settings as
      // parameters (StepData_ConfParameters), but still makes the file's header from the
      // statics (FILE_SCHEMA said AP203 over AP214 entities), so the statics are set on both.
      STEPControl_Controller::Init();
      const StaticsRestorer restoreStatics;
      Interface_Static::SetCVal("write.step.schema", "AP214CD");
      Interface_Static::SetCVal("write.step.unit", "MM");
      Interface_Static::SetIVal("write.surfacecurve.mode", 0);
      STEPControl_Writer writer;  // after the schema: its model's header is made here
      const IFSelect_ReturnStatus transferred = writer.Transfer(withCurves, STEPControl_AsIs);
      if (transferred != IFSelect_RetDone || writer.Write(temporary.c_str()) != IFSelect_RetDone)
        throw Error(ErrorKind::Io, "cannot write " + path);
    });
  });
}

}  // namespace sliceform
