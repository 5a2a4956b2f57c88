# SPDX-License-Identifier: LGPL-2.1-or-later
"""One parameter schema, owned by the core (issue 16): the feature's properties (names,
groups, tooltips, defaults, choices, ranges), the CLI's `design --help` (options, help text,
defaults) and the preferences page (made from it: gui_smoke.py) all say what
sliceform_native.parameter_schema() says. Run through TestSliceform (tests/freecad/run.sh)."""
import os
import re
import subprocess
import unittest
import xml.etree.ElementTree as ET

import FreeCAD


def _squash(text):
    return " ".join(text.split())


class TestSliceformSchema(unittest.TestCase):
    def setUp(self):
        from sliceform_app import parameters

        self.schema = parameters.schema()
        self.doc = FreeCAD.newDocument("SliceformSchema")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def test_schema_is_complete(self):
        keys = [s["key"] for s in self.schema]
        self.assertEqual(len(keys), len(set(keys)))
        for s in self.schema:
            self.assertIn(s["kind"], ("real", "integer", "bool", "choice", "direction"), s["key"])
            self.assertTrue(s["help"] and s["label"] and s["group"], s["key"])
            if s["kind"] in ("real", "integer"):
                self.assertLessEqual(s["min"], s["default"], s["key"])
                self.assertLessEqual(s["default"], s["max"], s["key"])
                self.assertGreater(s["step"], 0, s["key"])
            if s["kind"] == "choice":
                self.assertEqual(s["default"], s["choices"][0], s["key"])

    def test_properties_are_made_from_the_schema(self):
        from sliceform_app import feature, parameters

        obj = self.doc.addObject("Part::FeaturePython", "Sliceform")
        feature.Sliceform(obj)
        for s in self.schema:
            name = s["property"]
            if not name:
                continue
            self.assertIn(name, obj.PropertiesList, s["key"])
            self.assertEqual(obj.getDocumentationOfProperty(name), s["help"], name)
            self.assertEqual(obj.getTypeIdOfProperty(name), parameters.freecad_type(s), name)
            if name != "FoldAngle":
                self.assertEqual(obj.getGroupOfProperty(name), s["group"], name)
            value = getattr(obj, name)
            value = value.Value if hasattr(value, "Value") else value
            if s["kind"] == "choice":
                extra = ["Custom"] if name == "SheetSize" else []
                self.assertEqual(obj.getEnumerationsOfProperty(name), s["choices"] + extra, name)
                self.assertEqual(value, s["default"], name)
            elif s["kind"] == "direction":
                self.assertEqual((value.x, value.y, value.z), tuple(s["default"]), name)
            else:
                self.assertAlmostEqual(float(value), float(parameters.FREECAD_DEFAULTS.get(name, s["default"])),
                                       msg=name)
        # A constrained property holds the schema's range: the core's limits.
        obj.Slices = 100000
        self.assertEqual(obj.Slices, parameters.spec("slices")["max"])
        obj.Slices = 1  # the core would refuse it: "the number of slices must be between 2 and 4096"
        self.assertEqual(obj.Slices, parameters.spec("slices")["min"])
        obj.TauA = -1.0
        self.assertEqual(obj.TauA, parameters.spec("tau_a")["min"])
        # Every parameter the feature hands the core is in the schema.
        obj.Source = self.doc.addObject("Part::Box", "Box")
        keys = set(parameters.core_params(obj))
        self.assertEqual(keys - {s["key"] for s in self.schema}, set())
        self.assertEqual({s["key"] for s in self.schema if s["property"] and s["property"] != "FoldAngle"}, keys)

    def test_cli_help_says_what_the_schema_says(self):
        cli = os.environ.get("SLICEFORM_CLI")
        if not cli or not os.path.exists(cli):
            self.fail("SLICEFORM_CLI is not set to the built sliceform program (tests/freecad/run.sh sets it)")
        text = subprocess.run([cli, "design", "--help"], capture_output=True, text=True, check=True).stdout
        squashed = _squash(text)
        for s in self.schema:
            if not s["option"]:
                continue
            match = re.search(r"^\s+(?:-\w,)?{}\b(.*)$".format(re.escape(s["option"])), text, re.M)
            self.assertIsNotNone(match, s["option"])
            self.assertIn(_squash(s["help"]), squashed, s["option"])
            # CLI11 2.3 (Debian 12) shows a default as "FLOAT=4", 2.4 (Debian 13) as "FLOAT [4]".
            shown = re.match(r"\s*(?:FLOAT|INT|TEXT\S*)(?:=| \[)([^\s\]]+)", match.group(1))
            if s["kind"] in ("real", "integer"):
                self.assertIsNotNone(shown, s["option"])
                self.assertAlmostEqual(float(shown.group(1)), float(s["default"]), msg=s["option"])
            elif s["kind"] == "choice":
                self.assertEqual(shown.group(1), s["default"], s["option"])
                if s["key"] != "sheet":  # WxH too
                    self.assertIn("{" + ",".join(s["choices"]) + "}", match.group(1), s["option"])

    def test_preferences_are_schema_parameters(self):
        """The preferences page is made from the schema (gui_smoke.py opens it): each of its
        fields is a schema parameter, stored as FreeCAD's preference widgets store it."""
        from sliceform_app import feature

        by_property = {s["property"]: s for s in self.schema if s["property"]}
        self.assertTrue(all(name in by_property for name in feature.PREFERRED))

    def test_translation_template_holds_every_string(self):
        """Resources/translations/Sliceform.ts (scripts/update-translations) holds every string
        the workbench marks for translation and every schema label and tooltip; and no string
        shown to the user is left unmarked."""
        import ast
        import glob

        from sliceform_app import ADDON_DIR

        ts = ET.parse(os.path.join(ADDON_DIR, "Resources", "translations", "Sliceform.ts")).getroot()
        template = {(c.findtext("name"), m.findtext("source")) for c in ts.iter("context") for m in c.iter("message")}
        sources = glob.glob(os.path.join(ADDON_DIR, "Gui", "sliceform_gui", "*.py"))
        sources += glob.glob(os.path.join(ADDON_DIR, "App", "sliceform_app", "*.py"))
        sources.append(os.path.join(ADDON_DIR, "InitGui.py"))
        # Calls that put their string arguments in front of the user.
        shown = {"setText", "QLabel", "QPushButton", "setWindowTitle", "setToolTip", "setPlainText", "addRow",
                 "PrintMessage", "PrintWarning", "information", "warning", "critical", "question",
                 "getSaveFileName", "getOpenFileName", "getExistingDirectory", "QCheckBox", "QGroupBox",
                 "setStatusTip", "showMessage", "setPlaceholderText", "addButton", "setTitle"}
        marked, unmarked = set(), []
        for path in sources:
            with open(path) as f:
                tree = ast.parse(f.read())
            for node in ast.walk(tree):
                if not isinstance(node, ast.Call):
                    continue
                name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
                literals = [a.value for a in node.args if isinstance(a, ast.Constant) and isinstance(a.value, str)]
                if name in ("translate", "QT_TRANSLATE_NOOP") and len(literals) == 2:
                    marked.add(tuple(literals))
                if name in shown:
                    for a in node.args:
                        text = a.func.value if (isinstance(a, ast.Call) and isinstance(a.func, ast.Attribute)
                                                and a.func.attr == "format") else a
                        if isinstance(text, ast.JoinedStr) or (
                                isinstance(text, ast.Constant) and isinstance(text.value, str)
                                and any(ch.isalpha() for ch in text.value)):
                            unmarked.append("{}:{} {}".format(os.path.basename(path), node.lineno, name))
        self.assertGreater(len(marked), 40)
        self.assertEqual(sorted(marked - template), [], "run scripts/update-translations")
        self.assertEqual(unmarked, [], "user-visible strings not marked for translation")
        for s in self.schema:
            if s["property"]:
                self.assertIn(("Sliceform", s["label"]), template, s["key"])
                self.assertIn(("App::Property", s["help"]), template, s["key"])


if __name__ == "__main__":
    unittest.main()
