# SPDX-License-Identifier: LGPL-2.1-or-later
"""Headless FreeCAD tests: the addon as installed in a throwaway user Mod folder.
Run by tests/freecad/run.sh through `freecadcmd -t TestSliceform`."""
import math
import os
import sys
import unittest

import FreeCAD
import Mesh
import Part


class TestInstalledAddon(unittest.TestCase):
    def test_init_put_the_packages_on_the_path(self):
        import sliceform_app
        import sliceform_gui

        self.assertTrue(os.path.isfile(os.path.join(sliceform_app.ADDON_DIR, "Init.py")))
        self.assertTrue(os.path.isfile(sliceform_gui.icon_path("Sliceform.svg")))
        self.assertIn("Sliceform", sliceform_app.ADDON_DIR)

    def test_native_module_imports_from_the_addon(self):
        from sliceform_app import native

        core = native()
        self.assertIn(os.path.join("Mod", "Sliceform"), core.__file__)
        self.assertRegex(core.__version__, r"^\d+\.\d+\.\d+$")

    def test_package_xml_is_read_by_this_freecad(self):
        # The Addon Manager's metadata, as FreeCAD itself parses it: the name, the version
        # of the compiled core, the oldest FreeCAD tested, and no placeholder addresses.
        import sliceform_app
        from sliceform_app import native

        path = os.path.join(sliceform_app.ADDON_DIR, "package.xml")
        metadata = FreeCAD.Metadata(path)
        self.assertEqual(metadata.Name, "Sliceform")
        self.assertEqual(metadata.Version, native().__version__)
        self.assertEqual(str(metadata.FreeCADMin), "0.20.0")
        self.assertEqual([w.Classname for w in metadata.Content["workbench"]], ["SliceformWorkbench"])
        self.assertTrue(metadata.License)
        self.assertNotIn("example.", open(path).read())

    def test_missing_native_module_gives_a_clear_error(self):
        import sliceform_app

        saved = sys.modules.pop("sliceform_native", None)  # None if not imported yet
        sys.modules["sliceform_native"] = None  # makes the import fail
        try:
            with self.assertRaises(sliceform_app.NativeModuleMissing) as caught:
                sliceform_app.native()
            self.assertIn("README", str(caught.exception))
        finally:
            del sys.modules["sliceform_native"]
            if saved is not None:
                sys.modules["sliceform_native"] = saved


class TestBrepExchange(unittest.TestCase):
    def test_brep_string_round_trips(self):
        from sliceform_app import native, shapes

        solid = Part.makeTorus(20, 5).cut(Part.makeBox(10, 10, 10))
        back = shapes.shape_from_brep(native().brep_round_trip(solid.exportBrepToString()))
        self.assertEqual(len(back.Faces), len(solid.Faces))
        self.assertAlmostEqual(back.Volume, solid.Volume, delta=1e-9 * solid.Volume)
        self.assertAlmostEqual(back.Area, solid.Area, delta=1e-9 * solid.Area)

    def test_bad_brep_string_raises_the_core_error(self):
        from sliceform_app import native

        core = native()
        with self.assertRaises(core.Error):
            core.brep_round_trip("not a brep")
        with self.assertRaises(core.Error):
            core.brep_round_trip("")


class TestSlicingInFreeCAD(unittest.TestCase):
    def setUp(self):
        self.doc = FreeCAD.newDocument("SliceformTest")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def test_sections_of_a_placed_cylinder_are_exact_circles(self):
        from sliceform_app import slices

        cyl = self.doc.addObject("Part::Cylinder", "Cylinder")
        cyl.Radius, cyl.Height = 10, 30
        # Lying along X and moved: sections along X are discs, in global coordinates.
        cyl.Placement = FreeCAD.Placement(FreeCAD.Vector(100, 0, 0), FreeCAD.Rotation(FreeCAD.Vector(0, 1, 0), 90))
        self.doc.recompute()
        u_set, v_set = slices.slice_object(cyl, count=6)
        for s in u_set["slices"]:
            self.assertAlmostEqual(s["area"], math.pi * 100, delta=1e-9 * math.pi * 100)
            self.assertEqual([e.Curve.TypeId for e in s["shape"].Edges], ["Part::GeomCircle"])
            self.assertTrue(100 < s["position"] < 130)
            self.assertAlmostEqual(s["shape"].BoundBox.XMin, s["position"], delta=1e-7)
        # Along Y the sections are rectangles 30 long and 2*sqrt(r^2 - y^2) high.
        for s in v_set["slices"]:
            expected = 30 * 2 * math.sqrt(100 - s["position"] ** 2)
            self.assertAlmostEqual(s["area"], expected, delta=1e-9 * expected)
            self.assertAlmostEqual(s["shape"].Area, s["area"], delta=1e-9 * expected)

    def test_core_area_matches_freecad_own_section(self):
        from sliceform_app import slices

        box = self.doc.addObject("Part::Box", "Box")
        box.Length, box.Width, box.Height = 40, 30, 20
        hole = self.doc.addObject("Part::Cylinder", "Hole")
        hole.Radius, hole.Height = 6, 40
        hole.Placement.Base = FreeCAD.Vector(20, 15, -10)
        cut = self.doc.addObject("Part::Cut", "Cut")
        cut.Base, cut.Tool = box, hole
        self.doc.recompute()
        u_set, _ = slices.slice_object(cut, count=5)
        for s in u_set["slices"]:
            wires = cut.Shape.slice(FreeCAD.Vector(1, 0, 0), s["position"])
            theirs = sum(Part.Face(w).Area for w in wires)
            self.assertAlmostEqual(s["area"], theirs, delta=1e-6 * theirs)

    def test_mesh_feature_is_sliced_as_triangles(self):
        from sliceform_app import slices

        mesh = self.doc.addObject("Mesh::Feature", "Ball")
        mesh.Mesh = Mesh.createSphere(10, 64)
        mesh.Placement.Base = FreeCAD.Vector(0, 0, 50)
        self.doc.recompute()
        u_set, _ = slices.slice_object(mesh, count=4)
        for s in u_set["slices"]:
            exact = math.pi * (100 - s["position"] ** 2)
            self.assertAlmostEqual(s["area"], exact, delta=0.02 * exact)  # a 64-segment sphere
            self.assertAlmostEqual(s["shape"].Area, s["area"], delta=1e-6 * exact)
            self.assertAlmostEqual(s["shape"].BoundBox.Center.z, 50, delta=0.5)

    def test_open_mesh_is_refused_naming_the_edges(self):
        from sliceform_app import native, shapes, slices

        open_mesh = Mesh.createBox(10, 10, 10)
        open_mesh.removeFacets([0])
        mesh = self.doc.addObject("Mesh::Feature", "Open")
        mesh.Mesh = open_mesh
        self.doc.recompute()
        topo = native().mesh_topology(*shapes.mesh_lists_of(mesh))
        self.assertFalse(topo["closed"])
        self.assertEqual(topo["boundary_edges"], 3)
        with self.assertRaisesRegex(native().Error, "not closed: 3 boundary edges in 1 hole"):
            slices.slice_object(mesh, count=4)

    def test_make_slices_adds_one_compound(self):
        from sliceform_app import slices

        sphere = self.doc.addObject("Part::Sphere", "Sphere")
        sphere.Radius = 10
        self.doc.recompute()
        feature = slices.make_slices(self.doc, sphere, count=8)
        self.assertEqual(len(feature.Shape.Faces), 16)
        self.assertEqual(feature.Shape.ShapeType, "Compound")
        self.assertIn("Sphere", feature.Label)

    def test_a_face_is_not_a_solid(self):
        from sliceform_app import native, slices

        face = self.doc.addObject("Part::Plane", "Plane")
        self.doc.recompute()
        with self.assertRaisesRegex(native().Error, "no closed solid"):
            slices.slice_object(face, count=4)


# The feature's tests live in their own file; importing the class runs them here too.
from TestSliceformFeature import TestSliceformFeature  # noqa: E402,F401
from TestSliceformChildren import TestSliceformChildren  # noqa: E402,F401
from TestSliceformSchema import TestSliceformSchema  # noqa: E402,F401


class TestDirectionsInTheBinding(unittest.TestCase):
    def test_auto_directions_stand_a_lamp_up(self):
        from sliceform_app import native

        # A round foot, a stem and a ball, lying on its side (foot towards -Y).
        lamp = Part.makeCylinder(40, 6).fuse([Part.makeCylinder(8, 60, FreeCAD.Vector(0, 0, 6)),
                                              Part.makeSphere(30, FreeCAD.Vector(0, 0, 90))])
        lamp.rotate(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(1, 0, 0), -90)
        d = native().design({"brep": lamp.exportBrepToString(), "name": "lamp"},
                            {"directions": "auto", "slices": 32})
        import json

        report = json.loads(d.report_json())
        chosen = report["directions"]["frames"][report["directions"]["chosen"]]
        u, v = FreeCAD.Vector(*chosen["u"]), FreeCAD.Vector(*chosen["v"])
        up = u.cross(v)
        self.assertGreater(up.y, 0.999, chosen["name"])  # the foot is down: W = +Y here
        self.assertEqual(report["parameters"]["u"], chosen["u"])
        self.assertTrue(report["verdict"]["buildable"], report["verdict"]["problems"])

    def test_unknown_directions_mode_is_refused(self):
        from sliceform_app import native

        with self.assertRaises(native().Error):
            native().design({"brep": Part.makeBox(50, 40, 30).exportBrepToString()}, {"directions": "sideways"})

    def test_feature_directions_property(self):
        from sliceform_app import feature

        doc = FreeCAD.newDocument("Directions")
        try:
            box = doc.addObject("Part::Box", "Box")
            box.Length, box.Width, box.Height = 40, 120, 60
            doc.recompute()
            given = feature.makeSliceform(box, Slices=24)
            self.assertEqual(given.Directions, "given")  # from Python and in older documents
            self.assertEqual(given.ChosenDirections, "given")
            chosen = feature.makeSliceform(box, Slices=24, Directions="auto")
            self.assertIn(" up, ", chosen.ChosenDirections)
            self.assertTrue(chosen.Buildable, chosen.Report)
        finally:
            FreeCAD.closeDocument(doc.Name)


class TestAssemblySteps(unittest.TestCase):
    def test_steps_follow_the_assembly_order_and_name_placed_partners(self):
        import json

        from sliceform_app import assembly_steps, native

        torus = Part.makeTorus(40, 12)
        report = json.loads(native().design({"brep": torus.exportBrepToString()}, {"slices": 32}).report_json())
        steps = assembly_steps.steps(report)
        self.assertEqual([pid for pid, _ in steps], report["assembly_order"])
        self.assertIn("upright", steps[0][1])
        placed = set()
        for pid, text in steps:
            named = set(t.strip(",.;") for t in text.split(": ", 2)[2].split() if t[:1] in "UV" and t[1:2].isdigit())
            self.assertTrue(named <= placed, (pid, named - placed))  # only partners already there
            placed.add(pid)
        self.assertTrue(any("onto" in text for _, text in steps[1:]))
