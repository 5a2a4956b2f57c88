// SPDX-License-Identifier: LGPL-2.1-or-later
#include "assembly/step_text.hpp"

#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_Hyperbola.hxx>
#include <Geom_Line.hxx>
#include <Geom_Parabola.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Lin.hxx>

#include <charconv>
#include <cmath>
#include <ctime>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sliceform {
namespace {

// Part 21's real: the shortest digits that read back as the same double (OCCT's writer
// rounds to 15 significant digits), with a point and a capital E. False, with nothing
// written, for an infinite or undefined value.
bool real(std::string& out, double v) {
  if (!std::isfinite(v)) return false;
  char digits[32];
  const std::to_chars_result r = std::to_chars(digits, digits + sizeof digits, v);
  const std::string_view s(digits, static_cast<size_t>(r.ptr - digits));
  const size_t e = s.find('e');
  const std::string_view mantissa = s.substr(0, e);
  out += mantissa;
  if (mantissa.find('.') == std::string_view::npos) out += '.';
  if (e != std::string_view::npos) out += 'E', out += s.substr(e + 1);
  return true;
}

// The entities of one file, numbered as they are made; an entity may name one made later
// (reserve() gives its number first): Part 21 allows any order.
class Entities {
 public:
  int reserve() { return ++last_; }
  int add(const std::string& body) { return define(reserve(), body); }
  int define(int id, const std::string& body) {
    text_ += '#';
    text_ += std::to_string(id);
    text_ += " = ";
    text_ += body;
    text_ += ";\n";
    return id;
  }
  const std::string& text() const { return text_; }

 private:
  int last_ = 0;
  std::string text_;
};

std::string ref(int id) {
  return "#" + std::to_string(id);
}

std::string refs(const std::vector<int>& ids) {
  std::string s = "(";
  for (size_t i = 0; i < ids.size(); ++i) s += (i ? "," : "") + ref(ids[i]);
  return s + ")";
}

// Writes the geometry and topology of the faces; `ok` turns false at the first thing it
// cannot write.
class Writer {
 public:
  Entities e;
  bool ok = true;

  // `v` written into `out`; a value that is not finite spoils the file.
  void number(std::string& out, double v) {
    if (!real(out, v)) ok = false;
  }
  int triple(const char* type, const gp_XYZ& p) {
    std::string body = type;
    body += "('',(";
    number(body, p.X()), body += ',', number(body, p.Y()), body += ',', number(body, p.Z());
    return e.add(body + "))");
  }
  int point(const gp_Pnt& p) { return triple("CARTESIAN_POINT", p.XYZ()); }
  int direction(const gp_Dir& d) { return triple("DIRECTION", d.XYZ()); }
  int axes(const gp_Pnt& origin, const gp_Dir& z, const gp_Dir& x) {
    const int o = point(origin), dz = direction(z), dx = direction(x);
    return e.add("AXIS2_PLACEMENT_3D(''," + ref(o) + "," + ref(dz) + "," + ref(dx) + ")");
  }
  int axes(const gp_Ax2& a) { return axes(a.Location(), a.Direction(), a.XDirection()); }

  // A conic named `type` about `a`, with its radii.
  int conic(const char* type, const gp_Ax2& a, std::initializer_list<double> radii) {
    const int at = axes(a);
    std::string body = std::string(type) + "(''," + ref(at);
    for (const double r : radii) body += ',', number(body, r);
    return e.add(body + ")");
  }

  int bspline(const Handle(Geom_BSplineCurve) & given) {
    Handle(Geom_BSplineCurve) c = given;
    if (c->IsPeriodic()) {  // as OCCT's writer: the same curve over one period, clamped
      c = Handle(Geom_BSplineCurve)::DownCast(given->Copy());
      c->SetNotPeriodic();
    }
    std::vector<int> poles;
    for (int i = 1; i <= c->NbPoles(); ++i) poles.push_back(point(c->Pole(i)));
    std::string mults = "(", knots = "(", weights = "(";
    for (int i = 1; i <= c->NbKnots(); ++i) {
      mults += (i > 1 ? "," : "") + std::to_string(c->Multiplicity(i));
      if (i > 1) knots += ',';
      number(knots, c->Knot(i));
    }
    for (int i = 1; i <= c->NbPoles(); ++i) {
      if (i > 1) weights += ',';
      number(weights, c->Weight(i));
    }
    mults += ')', knots += ')', weights += ')';
    const std::string closed = c->IsClosed() ? ".T." : ".F.";
    const std::string degree = std::to_string(c->Degree());
    if (!c->IsRational())
      return e.add("B_SPLINE_CURVE_WITH_KNOTS(''," + degree + "," + refs(poles) + ",.UNSPECIFIED.," + closed +
                   ",.F.," + mults + "," + knots + ",.UNSPECIFIED.)");
    return e.add("( BOUNDED_CURVE() B_SPLINE_CURVE(" + degree + "," + refs(poles) + ",.UNSPECIFIED.," +
                 closed + ",.F.) B_SPLINE_CURVE_WITH_KNOTS(" + mults + "," + knots +
                 ",.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE(" +
                 weights + ") REPRESENTATION_ITEM('') )");
  }

  // The curve under any trimming, as STEP has it; 0 for a kind not written here.
  int curve(Handle(Geom_Curve) c) {
    while (const auto t = Handle(Geom_TrimmedCurve)::DownCast(c)) c = t->BasisCurve();
    if (const auto l = Handle(Geom_Line)::DownCast(c)) {
      const int p = point(l->Lin().Location()), d = direction(l->Lin().Direction());
      const int v = e.add("VECTOR(''," + ref(d) + ",1.)");
      return e.add("LINE(''," + ref(p) + "," + ref(v) + ")");
    }
    if (const auto k = Handle(Geom_Circle)::DownCast(c)) return conic("CIRCLE", k->Position(), {k->Radius()});
    if (const auto k = Handle(Geom_Ellipse)::DownCast(c))
      return conic("ELLIPSE", k->Position(), {k->MajorRadius(), k->MinorRadius()});
    if (const auto k = Handle(Geom_Hyperbola)::DownCast(c))
      return conic("HYPERBOLA", k->Position(), {k->MajorRadius(), k->MinorRadius()});
    if (const auto k = Handle(Geom_Parabola)::DownCast(c))
      return conic("PARABOLA", k->Position(), {k->Focal()});
    if (const auto b = Handle(Geom_BSplineCurve)::DownCast(c)) return bspline(b);
    if (const auto b = Handle(Geom_BezierCurve)::DownCast(c))
      return bspline(GeomConvert::CurveToBSplineCurve(b));
    ok = false;
    return 0;
  }

  int vertex(const TopoDS_Vertex& v) {
    if (const int* known = vertices_.Seek(v)) return *known;
    const int id = e.add("VERTEX_POINT(''," + ref(point(BRep_Tool::Pnt(v))) + ")");
    vertices_.Bind(v, id);
    return id;
  }

  // The edge's curve from its first vertex to its last, in the curve's own sense.
  int edge(const TopoDS_Edge& given) {
    const TopoDS_Edge forward = TopoDS::Edge(given.Oriented(TopAbs_FORWARD));
    if (const int* known = edges_.Seek(forward)) return *known;
    TopLoc_Location at;
    double first = 0, last = 0;
    Handle(Geom_Curve) c = BRep_Tool::Curve(forward, at, first, last);
    if (c.IsNull()) {
      ok = false;
      return 0;
    }
    if (!at.IsIdentity()) c = Handle(Geom_Curve)::DownCast(c->Transformed(at.Transformation()));
    TopoDS_Vertex a, b;
    TopExp::Vertices(forward, a, b);
    if (a.IsNull() || b.IsNull()) {
      ok = false;
      return 0;
    }
    const int va = vertex(a), vb = vertex(b), curveId = curve(c);
    const int id = e.add("EDGE_CURVE(''," + ref(va) + "," + ref(vb) + "," + ref(curveId) + ",.T.)");
    edges_.Bind(forward, id);
    return id;
  }

  // The wire's edges end to end, each oriented as the face runs along it.
  int loop(const TopoDS_Wire& wire, const TopoDS_Face& face) {
    int count = 0;
    for (TopoDS_Iterator it(wire); it.More(); it.Next()) ++count;
    std::vector<int> oriented;
    TopoDS_Vertex start, end;
    for (BRepTools_WireExplorer x(wire, face); x.More(); x.Next()) {
      const TopoDS_Edge& current = x.Current();
      if (current.Orientation() != TopAbs_FORWARD && current.Orientation() != TopAbs_REVERSED) ok = false;
      // Each edge begins where the last ended, and the last ends where the first began.
      const TopoDS_Vertex from = TopExp::FirstVertex(current, true), to = TopExp::LastVertex(current, true);
      if (start.IsNull())
        start = from;
      else if (!from.IsSame(end))
        ok = false;
      end = to;
      const bool sense = current.Orientation() == TopAbs_FORWARD;
      oriented.push_back(
          e.add("ORIENTED_EDGE('',*,*," + ref(edge(current)) + "," + (sense ? ".T." : ".F.") + ")"));
    }
    if (static_cast<int>(oriented.size()) != count || oriented.empty() || !end.IsSame(start)) ok = false;
    return e.add("EDGE_LOOP(''," + refs(oriented) + ")");
  }

  // The face, in the coordinates of its own part (without its placement).
  int face(const TopoDS_Face& given) {
    if (given.Orientation() != TopAbs_FORWARD && given.Orientation() != TopAbs_REVERSED) ok = false;
    const TopoDS_Face face = TopoDS::Face(given.Oriented(TopAbs_FORWARD));
    TopLoc_Location at;
    Handle(Geom_Surface) s = BRep_Tool::Surface(face, at);
    while (const auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = t->BasisSurface();
    const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(s);
    if (plane.IsNull()) {
      ok = false;
      return 0;
    }
    gp_Ax3 position = plane->Position();
    if (!at.IsIdentity()) position.Transform(at.Transformation());
    // STEP's placement is right-handed: on a plane whose axes are not, the face's normal
    // (X x Y) is against the placement's axis.
    const bool sense = (given.Orientation() == TopAbs_FORWARD) == position.Direct();
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    std::vector<int> bounds;
    for (TopoDS_Iterator w(face); w.More(); w.Next()) {
      if (w.Value().ShapeType() != TopAbs_WIRE) {
        ok = false;
        continue;
      }
      const TopoDS_Wire& wire = TopoDS::Wire(w.Value());
      const char* kind = wire.IsSame(outer) ? "FACE_OUTER_BOUND" : "FACE_BOUND";
      bounds.push_back(e.add(std::string(kind) + "(''," + ref(loop(wire, face)) + ",.T.)"));
    }
    const int p = e.add("PLANE(''," +
                        ref(axes(position.Location(), position.Direction(), position.XDirection())) + ")");
    return e.add("ADVANCED_FACE(''," + refs(bounds) + "," + ref(p) + "," + (sense ? ".T." : ".F.") + ")");
  }

 private:
  TopTools_DataMapOfShapeInteger vertices_, edges_;
};

// Part 21's string: an apostrophe written twice.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// A product named `name` in the contexts given: its PRODUCT_DEFINITION and the
// PRODUCT_DEFINITION_SHAPE of that.
std::pair<int, int> product(Entities& e, const std::string& name, int mechanical, int definitionContext) {
  const int p = e.add("PRODUCT(" + quoted(name) + "," + quoted(name) + ",''," + refs({mechanical}) + ")");
  e.add("PRODUCT_TYPE('part',$," + refs({p}) + ")");
  const int formation = e.add("PRODUCT_DEFINITION_FORMATION('',''," + ref(p) + ")");
  const int definition =
      e.add("PRODUCT_DEFINITION('design',''," + ref(formation) + "," + ref(definitionContext) + ")");
  return {definition, e.add("PRODUCT_DEFINITION_SHAPE('',''," + ref(definition) + ")")};
}

std::string timeStamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  return text;
}

// The faces of nested compounds, each placed where the compounds put it; false when
// anything else is found.
bool facesOf(const TopoDS_Shape& shape, std::vector<TopoDS_Face>& out) {
  if (shape.ShapeType() == TopAbs_FACE) {
    out.push_back(TopoDS::Face(shape));
    return true;
  }
  if (shape.ShapeType() != TopAbs_COMPOUND) return false;
  for (TopoDS_Iterator it(shape); it.More(); it.Next())
    if (!facesOf(it.Value(), out)) return false;
  return true;
}

}  // namespace

bool planarFacesStep(const TopoDS_Shape& shape, std::string& text, const std::vector<std::string>& names) {
  text.clear();
  std::vector<TopoDS_Face> faces;
  if (shape.IsNull() || !facesOf(shape, faces)) return false;
  Writer w;
  Entities& e = w.e;
  const int application =
      e.add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')");
  e.add("APPLICATION_PROTOCOL_DEFINITION('committee draft','automotive_design',1997," + ref(application) +
        ")");
  const int mechanical = e.add("MECHANICAL_CONTEXT(''," + ref(application) + ",'mechanical')");
  const int definitionContext =
      e.add("PRODUCT_DEFINITION_CONTEXT('part definition'," + ref(application) + ",'design')");
  const int length = e.add("( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) )");
  const int angle = e.add("( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) )");
  const int solid = e.add("( NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT() )");
  const int uncertainty = e.add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07)," + ref(length) +
                                ",'distance_accuracy_value','confusion accuracy')");
  const int context =
      e.add("( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT(" +
            refs({uncertainty}) + ") GLOBAL_UNIT_ASSIGNED_CONTEXT(" + refs({length, angle, solid}) +
            ") REPRESENTATION_CONTEXT('Context #1','3D Context with UNIT and UNCERTAINTY') )");
  const auto [assembly, assemblyShape] = product(e, "assembly", mechanical, definitionContext);
  const int origin = w.axes(gp_Pnt(0, 0, 0), gp::DZ(), gp::DX());
  const int assemblyRepresentation = e.reserve();
  e.add("SHAPE_DEFINITION_REPRESENTATION(" + ref(assemblyShape) + "," + ref(assemblyRepresentation) + ")");
  std::vector<int> placements{origin};
  int k = 0;
  for (const TopoDS_Face& located : faces) {
    if (!w.ok) break;
    const gp_Trsf t = located.Location().Transformation();
    if (std::abs(t.ScaleFactor() - 1) > 1e-12 || t.IsNegative()) return false;
    ++k;
    const std::string name = names.size() == faces.size() ? names[k - 1] : "patch " + std::to_string(k);
    const auto [part, partShape] = product(e, name, mechanical, definitionContext);
    const int face = w.face(TopoDS::Face(located.Located(TopLoc_Location())));
    const int shell = e.add("OPEN_SHELL(''," + refs({face}) + ")");
    const int model = e.add("SHELL_BASED_SURFACE_MODEL(''," + refs({shell}) + ")");
    const int representation =
        e.add("MANIFOLD_SURFACE_SHAPE_REPRESENTATION(''," + refs({origin, model}) + "," + ref(context) + ")");
    e.add("SHAPE_DEFINITION_REPRESENTATION(" + ref(partShape) + "," + ref(representation) + ")");
    // Placed as the face is: its part's origin carried to the placement's axes.
    const int placed = w.axes(gp_Pnt(t.TranslationPart()), gp::DZ().Transformed(t), gp::DX().Transformed(t));
    placements.push_back(placed);
    const int transformation =
        e.add("ITEM_DEFINED_TRANSFORMATION('',''," + ref(origin) + "," + ref(placed) + ")");
    const int relation =
        e.add("( REPRESENTATION_RELATIONSHIP('',''," + ref(representation) + "," +
              ref(assemblyRepresentation) + ") REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(" +
              ref(transformation) + ") SHAPE_REPRESENTATION_RELATIONSHIP() )");
    const int usage = e.add("NEXT_ASSEMBLY_USAGE_OCCURRENCE(" + quoted(std::to_string(k)) + ",'',''," +
                            ref(assembly) + "," + ref(part) + ",$)");
    const int usageShape =
        e.add("PRODUCT_DEFINITION_SHAPE('Placement','Placement of an item'," + ref(usage) + ")");
    e.add("CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(" + ref(relation) + "," + ref(usageShape) + ")");
  }
  if (!w.ok) return false;
  e.define(assemblyRepresentation, "SHAPE_REPRESENTATION(''," + refs(placements) + "," + ref(context) + ")");
  text = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('Sliceform assembly'),'2;1');\n";
  text += "FILE_NAME('assembly','" + timeStamp() + "',(''),(''),'Sliceform','Sliceform','');\n";
  text += "FILE_SCHEMA(('AUTOMOTIVE_DESIGN_CC2 { 1 2 10303 214 -1 1 5 4 }'));\nENDSEC;\nDATA;\n";
  text += e.text();
  text += "ENDSEC;\nEND-ISO-10303-21;\n";
  return true;
}

}  // namespace sliceform
