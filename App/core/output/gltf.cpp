// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/gltf.hpp"

#include <BRep_Builder.hxx>
#include <Message_ProgressRange.hxx>
#include <Poly_Triangle.hxx>
#include <Poly_Triangulation.hxx>
#include <Quantity_Color.hxx>
#include <Quantity_ColorRGBA.hxx>
#include <RWGltf_CafWriter.hxx>
#include <TColStd_IndexedDataMapOfStringString.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XCAFDoc_VisMaterial.hxx>
#include <XCAFDoc_VisMaterialPBR.hxx>
#include <XCAFDoc_VisMaterialTool.hxx>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "output/assembly_png.hpp"
#include "output/triangulate.hpp"
#include "support/atomic_file.hpp"
#include "support/error.hpp"
#include "support/occt_guard.hpp"

namespace sliceform {
namespace {

// One face per panel carrying only its triangulation (no surface, no edges): all the glTF
// writer reads. Flat paper: every node has the panel's normal.
TopoDS_Face meshedFace(const Panel3& panel) {
  const Triangles t = triangulate(panel.loops, panel.normal);
  if (t.corners.empty()) throw Error(ErrorKind::Geometry, "a patch outline encloses no area");
  Handle(Poly_Triangulation) mesh =
      new Poly_Triangulation(static_cast<int>(t.points.size()), static_cast<int>(t.corners.size()),
                             /*hasUVNodes=*/false, /*hasNormals=*/true);
  const gp_Dir normal(panel.normal.x, panel.normal.y, panel.normal.z);
  for (size_t i = 0; i < t.points.size(); ++i) {
    mesh->SetNode(static_cast<int>(i) + 1, gp_Pnt(t.points[i].x, t.points[i].y, t.points[i].z));
    mesh->SetNormal(static_cast<int>(i) + 1, normal);
  }
  for (size_t i = 0; i < t.corners.size(); ++i)
    mesh->SetTriangle(static_cast<int>(i) + 1,
                      Poly_Triangle(t.corners[i][0] + 1, t.corners[i][1] + 1, t.corners[i][2] + 1));
  TopoDS_Face face;
  BRep_Builder().MakeFace(face, mesh);
  return face;
}

// Paper: not metal (glTF's default metallicFactor is 1, which viewers show as dark chrome),
// rough, and two-sided, as both sides of a patch are seen.
TDF_Label paperMaterial(const Handle(XCAFDoc_VisMaterialTool) & materials, int family) {
  const PaperColour c = paperColour(family);
  XCAFDoc_VisMaterialPBR pbr;
  pbr.BaseColor = Quantity_ColorRGBA(Quantity_Color(c.r, c.g, c.b, Quantity_TOC_sRGB));
  pbr.Metallic = 0;
  pbr.Roughness = 0.9f;
  Handle(XCAFDoc_VisMaterial) material = new XCAFDoc_VisMaterial();
  material->SetPbrMaterial(pbr);
  material->SetFaceCulling(Graphic3d_TypeOfBackfacingModel_DoubleSided);
  return materials->AddMaterial(material, family == 0 ? "paper U" : "paper V");
}

// One free part per patch, named and with its family's paper. Each part is the patch inside
// a compound with no location of its own, so the fold pose goes into the vertices rather
// than into a node transform: every node sits at the identity and the accessors' bounds are
// the model's.
Handle(TDocStd_Document) document(const std::vector<Panel3>& panels) {
  Handle(TDocStd_Document) doc = new TDocStd_Document("BinXCAF");
  XCAFDoc_DocumentTool::Set(doc->Main());
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const Handle(XCAFDoc_VisMaterialTool) materials = XCAFDoc_DocumentTool::VisMaterialTool(doc->Main());
  const TDF_Label paper[2] = {paperMaterial(materials, 0), paperMaterial(materials, 1)};
  BRep_Builder builder;
  for (size_t k = 0; k < panels.size(); ++k) {
    TopoDS_Compound part;
    builder.MakeCompound(part);
    builder.Add(part, meshedFace(panels[k]));
    const TDF_Label label = shapes->AddShape(part, /*makeAssembly=*/false);
    TDataStd_Name::Set(label, TCollection_ExtendedString(("patch " + std::to_string(k + 1)).c_str()));
    materials->SetShapeMaterial(label, paper[panels[k].family == 1 ? 1 : 0]);
  }
  return doc;
}

void writeGlb(const Handle(TDocStd_Document) & doc, const std::string& file, const std::string& path) {
  RWGltf_CafWriter writer(file.c_str(), /*isBinary=*/true);
  RWMesh_CoordinateSystemConverter& axes = writer.ChangeCoordinateSystemConverter();
  axes.SetInputLengthUnit(0.001);  // our mm; the writer's output is metres
  axes.SetInputCoordinateSystem(RWMesh_CoordinateSystem_Zup);
  axes.SetOutputLengthUnit(1.0);
  axes.SetOutputCoordinateSystem(RWMesh_CoordinateSystem_glTF);
  TColStd_IndexedDataMapOfStringString info;
  info.Add("Generator", "Sliceform");
  if (!writer.Perform(doc, info, Message_ProgressRange())) throw Error(ErrorKind::Io, "cannot write " + path);
}

// A folder of our own beside the target, removed with what is left in it: the writer puts a
// side file "<name>.bin.tmp" next to the .glb, whose name is not unique to this process.
class PrivateFolder {
 public:
  PrivateFolder(const std::string& beside, const std::string& path) {
    std::string pattern = beside + ".gltf-XXXXXX";
    if (!::mkdtemp(pattern.data()))
      throw Error(ErrorKind::Io, "cannot write " + path + ": " + std::strerror(errno));
    path_ = pattern;
  }
  ~PrivateFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  PrivateFolder(const PrivateFolder&) = delete;
  PrivateFolder& operator=(const PrivateFolder&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace

void writeGltf(const std::vector<Panel3>& panels, const std::string& path) {
  if (panels.empty()) throw Error(ErrorKind::Io, "cannot write " + path + ": the assembly is empty");
  writeAtomically(path, [&](const std::string& temporary) {
    const PrivateFolder folder(temporary, path);
    const std::string glb = folder.file("assembly.glb");
    try {
      occtGuard("writing the glTF assembly", [&] { writeGlb(document(panels), glb, path); });
    } catch (const Error& e) {
      // Whatever OCCT stumbled on, the user sees a file that could not be written.
      if (e.kind() != ErrorKind::Io) throw Error(ErrorKind::Io, "cannot write " + path + ": " + e.what());
      throw;
    }
    std::error_code ec;
    std::filesystem::rename(glb, temporary, ec);
    if (ec) throw Error(ErrorKind::Io, "cannot write " + path + ": " + ec.message());
  });
}

}  // namespace sliceform
