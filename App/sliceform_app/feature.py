# SPDX-License-Identifier: LGPL-2.1-or-later
"""The parametric Sliceform feature (Part::FeaturePython). Its shape is the assembled
sliceform at FoldAngle; its children are a sketch per patch and a TechDraw page per sheet.
State lives in properties; the proxy keeps only the last design in memory (never saved),
so that a FoldAngle change re-poses the patches without designing again."""
import hashlib
import json

import FreeCAD
import Part

from sliceform_app import children, native, parameters, shapes


def initProperties(obj):
    """Adds what is missing and sets modes: the one schema migration, idempotent, called
    from __init__ and onDocumentRestored."""
    have = set(obj.PropertiesList)

    def add(kind, name, group, tip):
        if name not in have:
            obj.addProperty(kind, name, group, tip)
            return True
        return False

    add("App::PropertyLink", "Source", "Sliceform", "The solid, body or mesh to design a sliceform for")
    if add("App::PropertyAngle", "FoldAngle", "Sliceform", "Angle between the families: 90 popped up, small folds flat"):
        obj.FoldAngle = 90.0
    for name, kind, group, default, _key, tip in parameters.PARAMETERS:
        if add(kind, name, group, tip):
            if kind == "App::PropertyVector":
                setattr(obj, name, FreeCAD.Vector(*default))
            else:
                setattr(obj, name, default)
    for name, kind, tip in parameters.RESULTS:
        add(kind, name, "Results", tip)
        obj.setEditorMode(name, 1)  # read-only
    add("App::PropertyLink", "PatchGroup", "Children", "Group holding the patch sketches")
    add("App::PropertyLinkList", "PatchSketches", "Children", "One sketch per patch, in patch order")
    add("App::PropertyLinkList", "Pages", "Children", "One TechDraw page per sheet")
    add("App::PropertyLink", "SheetGroup", "Children", "Group holding the sheet geometry the pages show")
    for name in ("PatchGroup", "PatchSketches", "Pages", "SheetGroup"):
        obj.setEditorMode(name, 1)


def source_of(obj):
    """What the core takes for a source object: triangles for meshes, a BREP otherwise,
    both in global placement."""
    if obj is None:
        raise ValueError("the sliceform has no Source: link a solid, body or mesh")
    if shapes.is_mesh(obj):
        points, triangles = shapes.mesh_lists_of(obj)
        return {"points": points, "triangles": triangles, "name": obj.Label}
    return {"brep": shapes.brep_of(obj), "name": obj.Label}


def _key(source, params):
    digest = hashlib.sha1(json.dumps(params, sort_keys=True).encode())
    digest.update(source.get("brep", "").encode())
    digest.update(repr((source.get("points"), source.get("triangles"))).encode())
    return digest.hexdigest()


def _mm(value):
    return "-" if value is None else "{:.2f}".format(value)


def summary(report):
    c, i = report["certificate"], report["interlocks"]
    return "\n".join(
        [
            "{} patches, {} hinges".format(len(report["patches"]), len(report["hinges"])),
            "stable: {} (nullity {})".format("yes" if c["stable"] else "NO", c["nullity"]),
            "interlocks: {} found, {} repaired, {} remaining; {} cut-through(s); {} split patch(es)".format(
                i["found"], i["repaired"], i["remaining"], i["cut_throughs"], report["split_patches"]
            ),
            "smallest slot-to-edge distance {:.2f} mm; shortest hinge {:.2f} mm".format(
                report["min_slot_edge_distance_mm"], report["min_hinge_length_mm"]
            ),
            "closest stacked patches {} mm apart, {} mm of paper between their slots".format(
                _mm(report.get("min_patch_spacing_mm")), _mm(report.get("min_finger_mm"))
            ),
            "quality: volume IoU {:.3f}".format(report["quality"]["volume_iou"]),
            "sheets: {} {} ({:.0f} % used)".format(
                report["sheets"]["count"], report["sheets"]["name"], 100 * report["sheets"]["utilisation"]
            ),
        ]
        + ["cannot be built: " + p for p in report["verdict"]["problems"]]
    )


class Progress:
    """FreeCAD's progress indicator over the core's stages; stop() cancels the run."""

    STAGES = 6

    def __init__(self):
        self.bar = FreeCAD.Base.ProgressIndicator()
        self.bar.start("Designing the sliceform...", self.STAGES)
        self.cancelled = False

    def __call__(self, stage):
        self.bar.next(True)
        return not self.cancelled

    def stop(self):
        self.bar.stop()


class Sliceform:
    """Proxy of the Sliceform feature."""

    def __init__(self, obj):
        obj.Proxy = self
        initProperties(obj)
        self.design = None
        self.key = None

    def onDocumentRestored(self, obj):
        initProperties(obj)
        self.design, self.key = None, None

    # Nothing of the proxy is saved: FreeCAD 0.20 calls __getstate__, later versions dumps.
    def __getstate__(self):
        return None

    def __setstate__(self, state):
        self.design, self.key = None, None

    def dumps(self):
        return None

    def loads(self, state):
        self.design, self.key = None, None

    def execute(self, obj):
        source = source_of(obj.Source)
        params = parameters.core_params(obj)
        key = _key(source, params)
        if getattr(self, "design", None) is None or key != getattr(self, "key", None):
            progress = Progress()
            try:
                self.design = native().design(source, params, progress)
            except Exception:
                self.design, self.key = None, None
                raise
            finally:
                progress.stop()
            self.key = key
            report = json.loads(self.design.report_json())
            self.report = report
            self._set_results(obj, report)
            children.update_sketches(obj, self.design.flat_patches())
            children.update_pages(obj, self.design.sheets())
        shape = Part.Shape()
        shape.importBrepFromString(self.design.assembly(float(obj.FoldAngle.Value)))
        obj.Shape = shape

    def _set_results(self, obj, report):
        obj.PatchCount = len(report["patches"])
        obj.Stable = bool(report["certificate"]["stable"])
        obj.Interlocks = int(report["interlocks"]["remaining"])
        obj.SmallestSlotEdgeDistance = float(report["min_slot_edge_distance_mm"])
        obj.ShortestHinge = float(report["min_hinge_length_mm"])
        obj.MinPatchSpacing = float(report.get("min_patch_spacing_mm") or 0.0)
        obj.MinFinger = max(0.0, float(report.get("min_finger_mm") or 0.0))
        obj.Buildable = bool(report["verdict"]["buildable"])
        obj.VolumeIoU = float(report["quality"]["volume_iou"])
        obj.SheetCount = int(report["sheets"]["count"])
        obj.Report = summary(report)

    def report_json(self):
        """report.json's text of the last design, or None before the first recompute."""
        return self.design.report_json() if getattr(self, "design", None) is not None else None

    def write_files(self, folder, fold_angle=90.0):
        """Writes the same files as `sliceform design -o folder`."""
        if getattr(self, "design", None) is None:
            raise RuntimeError("recompute the sliceform first")
        return self.design.write_files(folder, fold_angle)


PREFERENCES = "User parameter:BaseApp/Preferences/Mod/Sliceform"
# Defaults a user sets once on the preferences page (Edit > Preferences > Sliceform).
PREFERRED = ("Thickness", "Clearance", "Kerf", "Slices", "SheetSize", "Margin", "Spacing")


def preferred_properties():
    """Property values from the preferences page, for the ones the user has set."""
    group = FreeCAD.ParamGet(PREFERENCES)
    values = {}
    for name in PREFERRED:
        if name == "Slices" and group.GetInt(name, 0) > 0:
            values[name] = group.GetInt(name)
        elif name == "SheetSize" and 0 <= group.GetInt(name, -1) < 3:
            values[name] = ("A4", "A3", "Letter")[group.GetInt(name)]  # a combo box stores its index
        elif name not in ("Slices", "SheetSize") and group.GetFloat(name, -1.0) >= 0:
            values[name] = group.GetFloat(name)
    return values


def makeSliceform(source, doc=None, **properties):
    """Adds a Sliceform feature for `source` (any shape-bearing object or a mesh), sets
    the preferred defaults and then the given properties, and recomputes. Returns it."""
    doc = doc or source.Document
    obj = doc.addObject("Part::FeaturePython", "Sliceform")
    Sliceform(obj)
    obj.Source = source
    obj.Label = "{} sliceform".format(source.Label)
    for name, value in dict(preferred_properties(), **properties).items():
        setattr(obj, name, value)
    if FreeCAD.GuiUp:
        from sliceform_gui import view_provider

        view_provider.ViewProviderSliceform(obj.ViewObject)
    doc.recompute()
    return obj
