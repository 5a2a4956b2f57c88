# SPDX-License-Identifier: LGPL-2.1-or-later
"""The parametric Sliceform feature (Part::FeaturePython). Its only input is its Source; its
shape is the assembled sliceform at FoldAngle. Its children (children.py: a patch per
patch, a TechDraw page per sheet) link to it and build themselves from its design. State
lives in properties; the proxy keeps the last few designs in memory (never saved), so that
a FoldAngle change re-poses the patches without designing again, and designs again on
demand where a design is needed after a reopen (Export, the report)."""
import array
import hashlib
import itertools
import json

import FreeCAD
import Part

from sliceform_app import geometry, native, observer, parameters, shapes, syncing

observer.install_observer()


QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP


# Properties of documents made before the children linked to the feature: the feature then
# linked its children (sketches in a group, pages, a group of sheet geometry).
OLD_CHILD_LINKS = ("PatchGroup", "PatchSketches", "Pages", "SheetGroup")


def initProperties(obj):
    """Adds what is missing and sets modes: the one schema migration, idempotent, called
    from __init__ and onDocumentRestored. Returns the objects an older document's feature
    linked as its children (to be replaced by children that link to it)."""
    have = set(obj.PropertiesList)

    def add(kind, name, group, tip):
        if name not in have:
            obj.addProperty(kind, name, group, tip)
            return True
        return False

    add("App::PropertyLink", "Source", "Sliceform",
        QT_TRANSLATE_NOOP("App::Property", "The solid, body or mesh to design a sliceform for"))
    fold = parameters.spec("fold_angle")
    if add("App::PropertyAngle", "FoldAngle", "Sliceform", fold["help"]):
        obj.FoldAngle = fold["default"]
    # A FoldAngle edit does not touch the feature: the proxy turns the patches itself, or
    # touches the feature when its design is not in memory (Sliceform.onChanged). The
    # Shape is what the feature computes from its inputs, never an input: setting it (the
    # new pose; an Undo) touches nothing either.
    obj.setPropertyStatus("FoldAngle", "Output")
    obj.setPropertyStatus("Shape", "Output")
    for name, kind, group, default, _key, tip in parameters.table():
        if add(kind, name, group, tip):
            if kind == "App::PropertyVector":
                setattr(obj, name, FreeCAD.Vector(*default))
            else:
                setattr(obj, name, default)
    for name, kind, tip in parameters.RESULTS:
        add(kind, name, "Results", tip)
        if "ReadOnly" not in obj.getEditorMode(name):
            obj.setEditorMode(name, 1)  # read-only
    if "ChildCount" not in have:
        # Output and hidden (attr 8 | 4): changing it never marks the feature for recompute.
        obj.addProperty("App::PropertyInteger", "ChildCount", "Children",
                        QT_TRANSLATE_NOOP("App::Property", "Patches and pages made for the design"), 12)
    old = []
    for name in OLD_CHILD_LINKS:
        if name in have:
            value = getattr(obj, name)
            old.extend(v for v in (value if isinstance(value, list) else [value]) if v is not None)
            obj.removeProperty(name)
    return old


def _old_children(objects):
    """The objects an old-style feature held, with what only they used: group members, a
    page's views, template and the views' sources."""
    out = []

    def visit(o):
        if o is None or o in out:
            return
        if o.TypeId == "App::DocumentObjectGroup":
            for member in o.Group:
                visit(member)
        elif o.TypeId == "TechDraw::DrawPage":
            for view in o.Views:
                visit(view)
            if o.Template is not None and not isinstance(o.Template, str):
                visit(o.Template)
        elif o.TypeId == "TechDraw::DrawViewPart":
            out.append(o)
            for source in o.Source:
                visit(source)
            return
        out.append(o)

    for o in objects:
        visit(o)
    return out


def mesh_source(obj, size=0.0):
    """What the core takes for a mesh source: its triangles in global placement. A size > 0
    scales it about the centre of its box so that its longest side is that long: the
    sliceform stands where the source is (a CAD source: Sliceform._source)."""
    points, triangles = shapes.mesh_lists_of(obj)
    if size > 0 and points:
        # Coordinate by coordinate, not point by point with a generator each: the same
        # numbers, a third of the time (fandisk: 10 of the 16 ms every edit spends here).
        columns = list(zip(*points))
        lo, hi = [min(c) for c in columns], [max(c) for c in columns]
        longest = max(h - l for h, l in zip(hi, lo))
        if longest > 0:
            f = size / longest
            cx, cy, cz = [(h + l) / 2 for h, l in zip(hi, lo)]
            points = [(cx + (x - cx) * f, cy + (y - cy) * f, cz + (z - cz) * f) for x, y, z in points]
    return {"points": points, "triangles": triangles, "name": obj.Label}


def _same_shape(a, b):
    """Whether a and b are one shape at one placement: the same TopoDS shape (isPartner; not
    isSame, which compares locations by identity, and Part.getShape makes a new one at every
    call), orientation and placement, to the bit."""
    return (a.isPartner(b) and a.Orientation == b.Orientation
            and tuple(a.Placement.toMatrix().A) == tuple(b.Placement.toMatrix().A))


class DesignError(Exception):
    """A failure the user can act on (bad source, parameters, or an unbuildable design):
    shown as the feature's error with the property names, never as a traceback."""


_saved_limit = []  # sys.tracebacklimit while it is held at 0, as [had it, its value]


def _quiet_traceback():
    """FreeCAD reports an exception raised in execute() with its Python stack, formatted by
    the traceback module as the recompute catches it. For a DesignError only the message
    is meant for the user: the stack is cut to nothing until the recompute is over."""
    import sys

    if not _saved_limit:
        _saved_limit[:] = [hasattr(sys, "tracebacklimit"), getattr(sys, "tracebacklimit", None)]
        sys.tracebacklimit = 0
        if FreeCAD.GuiUp:
            from PySide import QtCore

            QtCore.QTimer.singleShot(0, restore_traceback)


def restore_traceback():
    """Gives tracebacks back their length: at the end of every document recompute (the
    children's observer), at the start of the next execute, or on the GUI's next turn."""
    import sys

    if _saved_limit:
        had, value = _saved_limit
        if had:
            sys.tracebacklimit = value
        elif hasattr(sys, "tracebacklimit"):
            del sys.tracebacklimit
        del _saved_limit[:]


# The design's parameters that only the layout reads: the sheet, and the kerf, which moves
# only the cut paths (Design.relaid).
LAYOUT_KEYS = ("sheet", "margin", "spacing", "rotate", "kerf")


def _source_key(source):
    """A digest of what the core is given for the source (sized already): the BREP's text,
    or the mesh's coordinates and indices as machine numbers (repr took 13 ms on fandisk)."""
    digest = hashlib.sha1(source.get("brep", "").encode())
    if "points" in source:
        digest.update(array.array("d", itertools.chain.from_iterable(source["points"])).tobytes())
        digest.update(array.array("q", itertools.chain.from_iterable(source["triangles"])).tobytes())
    return digest.hexdigest()


def _key(source_key, params):
    return hashlib.sha1((json.dumps(params, sort_keys=True) + source_key).encode()).hexdigest()


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


def chosen_directions(report):
    """The frame `directions: auto` chose, as the ChosenDirections result; "given" else."""
    d = report.get("directions")
    if not d:
        return "given"
    u, v = report["parameters"]["u"], report["parameters"]["v"]
    return "{} (U {:.3f}, {:.3f}, {:.3f}; V {:.3f}, {:.3f}, {:.3f})".format(d["why"], *u, *v)


class Sliceform:
    """Proxy of the Sliceform feature. The design lives in memory only (a few recent ones,
    by a key of the source and the parameters), so a FoldAngle change re-poses the patches
    without designing again, and Cancel goes back to the design before at once."""

    Type = "Sliceform"
    KEEP = 3  # designs kept in memory

    def __init__(self, obj):
        obj.Proxy = self
        initProperties(obj)
        self._forget()

    def _forget(self):
        # key -> (design, report, flat patches, sheets, local faces, drawings by patch id)
        self.designs = {}
        self.unlaid = {}  # key -> the key of its inputs but the sheet's
        self.sources = {}  # key -> the key of its source
        # (placed shape, size, source, source key) of the last CAD source read: see _source
        self.last_source = None
        self.design, self.key, self.report = None, None, None
        self.posed = None  # ((the key of the patches posed, FoldAngle), the shape set then)

    def onDocumentRestored(self, obj):
        old = initProperties(obj)
        self._forget()
        if old:
            # An older document: its children were inputs of the feature. They go at the
            # next sync, which makes the new ones (Export and the tree work before that).
            self.old_children = [o.Name for o in _old_children(old)]

    # Only the type is saved: FreeCAD 0.20 calls __getstate__, later versions dumps.
    def __getstate__(self):
        return {"Type": self.Type}

    def __setstate__(self, state):
        self._forget()

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        self._forget()

    # --- the design, on demand ------------------------------------------------------------

    def _inputs(self, obj):
        params = parameters.core_params(obj)
        size = params.pop("size", 0.0)
        source, source_key = self._source(obj.Source, size)
        # FillHoles changes the model a mesh is read into: a design of it is another source's.
        filled = params.get("fill_holes") and "points" in source
        source_key += "+every hole filled" if filled else ""
        return source, params, source_key, _key(source_key, dict(params, size=size))

    def _source(self, source_obj, size):
        """What the core takes for the source (mesh_source, or a BREP for a CAD source, both
        in global placement and sized) and its digest. A CAD source whose placed shape is the
        very one read last time (the same TopoDS shape, which FreeCAD never changes in place:
        a recompute of the source makes new ones, at the same placement) at the same size is not
        written out again: at every edit its BREP was exported only to be digested
        (occt-misc Top, Bottom, Motor-c in FreeCAD 0.20 and 1.0: 44-98 ms an edit). The last shape is
        held, so no other shape can take its place in memory and seem the same."""
        if source_obj is None:
            raise DesignError(
                QT_TRANSLATE_NOOP("Sliceform", "the sliceform has no Source: link a solid, body or mesh")
            )
        if shapes.is_mesh(source_obj):
            source = mesh_source(source_obj, size)
            return source, _source_key(source)
        shape = shapes.placed_shape(source_obj)
        last = self.last_source
        if last is not None and last[1] == size and _same_shape(last[0], shape):
            return dict(last[2], name=source_obj.Label), last[3]
        source = {"brep": shapes.brep_of_shape(shape, size), "name": source_obj.Label}
        self.last_source = (shape, size, source, _source_key(source))
        return source, self.last_source[3]

    def _made_again(self, source, params, source_key, key, progress):
        """The design for these inputs from one in memory of the same source: laid out again
        if only the sheet or the kerf differs (a sheet, margin, spacing or kerf edit needs no
        new design), else designed again with the stages whose inputs did not change taken
        from it (Design.redesigned); designed anew if none has this source."""
        unlaid = _key(source_key, {k: v for k, v in params.items() if k not in LAYOUT_KEYS})
        self.unlaid[key], self.sources[key] = unlaid, source_key
        same_source = None
        for other, entry in self.designs.items():
            if self.unlaid.get(other) == unlaid:
                return entry[0].relaid({k: params[k] for k in LAYOUT_KEYS if k in params})
            if self.sources.get(other) == source_key:
                same_source = entry[0]
        if same_source is not None:
            return same_source.redesigned(params, progress)
        return native().design(source, params, progress)

    def ensure_design(self, obj):
        """The design for the feature's source and properties as they are: the one in
        memory, or designed now (after a reopen, an Undo or a Cancel). Raises DesignError
        with the property names when it cannot be made."""
        try:
            source, params, source_key, key = self._inputs(obj)
        except DesignError:
            raise
        except (ValueError, RuntimeError) as e:
            raise DesignError(parameters.property_message(str(e))) from None
        if key == self.key and self.design is not None:
            return self.design
        if key not in self.designs:
            progress = Progress()
            try:
                design = self._made_again(source, params, source_key, key, progress)
            except native().Error as e:
                raise DesignError(parameters.property_message(str(e))) from None
            finally:
                progress.stop()
            report = json.loads(design.report_json())
            self.designs[key] = (design, report, None, None, None, None)
            while len(self.designs) > self.KEEP:
                oldest = next(iter(self.designs))
                self.designs.pop(oldest)
                self.unlaid.pop(oldest, None)
                self.sources.pop(oldest, None)
        self.key = key
        self.design, self.report = self.designs[key][:2]
        return self.design

    def design_now(self, obj):
        """The design in memory when the feature is up to date (its children ask while a
        recompute builds them, right after the feature's own execute), else ensure_design."""
        if self.design is not None and obj.isValid() and "Touched" not in obj.State:
            return self.design
        return self.ensure_design(obj)

    def _cached(self, obj, slot, make):
        self.design_now(obj)
        return self._current(slot, make)

    def _current(self, slot, make):
        """Part `slot` of the current design's entry (self.key's), made by make(design) when
        first asked: for callers that know the design is current (during the feature's own
        execute the feature is still marked for recompute, and design_now would read the
        source again to say so)."""
        entry = list(self.designs[self.key])
        if entry[slot] is None:
            entry[slot] = make(self.design)
            self.designs[self.key] = tuple(entry)
        return entry[slot]

    def flat_patches(self, obj):
        """The flat patches of the current design (see sliceform_native.Design)."""
        return self._cached(obj, 2, lambda d: d.flat_patches())

    def sheets(self, obj):
        """The nested sheets of the current design."""
        return self._cached(obj, 3, lambda d: d.sheets())

    def local_faces(self, obj):
        """Each patch's paper in its plane's coordinates and that plane's placement, in
        flat_patches' order (geometry.local_face): what the patches show and the pose is
        made of, read from the core's BREP once a design."""
        self.design_now(obj)
        return self._current_local_faces()

    def _current_local_faces(self):
        def make(design):
            flat = self._current(2, lambda d: d.flat_patches())
            return [geometry.local_face(p, b) for p, b in zip(flat, design.patch_faces())]

        return self._current(4, make)

    def sheet_drawings(self, obj):
        """Patch id -> its drawing on its sheet (asked by every sheet drawing and engraving)."""
        return self._cached(obj, 5, lambda d: {p["id"]: p for sheet in self.sheets(obj)["sheets"] for p in sheet})

    # --- the feature ------------------------------------------------------------------------

    def onChanged(self, obj, prop):
        # FoldAngle is an output property (initProperties): its edits touch nothing. Up to
        # date, with its design in memory, the feature turns its patches now and stays
        # untouched: a recompute of the feature recomputes every child (FreeCAD enforces
        # its dependents), and TechDraw's views redo their hidden lines though nothing they
        # show changed (0.5 s of a FoldAngle edit on fandisk). Else it recomputes.
        if prop != "FoldAngle" or getattr(obj.Document, "Restoring", False) or not hasattr(self, "design"):
            return
        if self.design is None or not obj.isValid() or "Touched" in obj.State:
            obj.touch()
            return
        self._pose(obj, self.design)
        # What the user built on the sliceform's shape (a compound, a cut) follows the new
        # pose at the next recompute; its own children (the patches and pages, which link to
        # it by their Sliceform property) do not depend on the pose.
        for other in obj.InList:
            if getattr(other, "Sliceform", None) != obj:
                other.touch()

    def _pose(self, obj, design, again=True):
        """Sets the feature's shape: the patches turned to FoldAngle. Not `again` when the
        shape shows this design's patches at this angle already: a sheet, margin, spacing or
        kerf edit lays the same patches out anew and leaves them where they stand (fandisk,
        directions auto, FreeCAD 0.20, which copies the old shape for Undo: the feature's own
        part of a Margin edit 0.29 s, 0.12 s without it). An Undo puts back another shape:
        then it is posed again."""
        posed = (self.unlaid.get(self.key, self.key), float(obj.FoldAngle.Value))
        last = self.posed  # set by _forget, which every way to a proxy calls
        if not again and last is not None and last[0] == posed and obj.Shape.isPartner(last[1]):
            return
        # The patches' own faces, each moved to where the fold puts it (a location, the
        # geometry shared): not the core's assembly as a BREP of its own, read again at every
        # edit (fandisk: 1.9 MB, 55 ms of FreeCAD 1.0's Thickness edit, most of a FoldAngle
        # edit).
        faces = self._current_local_faces()
        folds = design.fold_transforms(posed[1])
        shape = Part.Compound(
            [face.transformed((FreeCAD.Placement(FreeCAD.Matrix(*fold)) * plane).toMatrix(), False)
             for (face, plane), fold in zip(faces, folds)]
        )
        obj.Shape = shape
        self.posed = (posed, obj.Shape)

    def execute(self, obj):
        restore_traceback()
        try:
            self._execute(obj)
        except DesignError:
            _quiet_traceback()
            raise

    def _execute(self, obj):
        design = self.ensure_design(obj)
        report = self.report
        self._set_results(obj, report)
        self._pose(obj, design, again=False)
        problems = report["verdict"]["problems"]
        if not report["verdict"]["buildable"]:
            raise DesignError(
                parameters.property_message(
                    FreeCAD.Qt.translate("Sliceform", "cannot be built: ")
                    + "; ".join(problems or [FreeCAD.Qt.translate("Sliceform", "see the report")])
                )
            )

    def _set_results(self, obj, report):
        values = {
            "PatchCount": len(report["patches"]),
            "Stable": bool(report["certificate"]["stable"]),
            "Interlocks": int(report["interlocks"]["remaining"]),
            "SmallestSlotEdgeDistance": float(report["min_slot_edge_distance_mm"]),
            "ShortestHinge": float(report["min_hinge_length_mm"]),
            "MinPatchSpacing": float(report.get("min_patch_spacing_mm") or 0.0),
            "MinFinger": max(0.0, float(report.get("min_finger_mm") or 0.0)),
            "Buildable": bool(report["verdict"]["buildable"]),
            "VolumeIoU": float(report["quality"]["volume_iou"]),
            "SheetCount": int(report["sheets"]["count"]),
            "ChosenDirections": chosen_directions(report),
            "Report": parameters.property_message(summary(report)),
        }
        for name, value in values.items():
            old = getattr(obj, name)
            old = old.Value if hasattr(old, "Value") else old
            if old != value:  # an unchanged result is not a change to undo
                setattr(obj, name, value)

    def report_json(self, obj):
        """report.json's text of the feature's design, designed now if needed."""
        return self.ensure_design(obj).report_json()

    def write_files(self, obj, folder, fold_angle=None):
        """Writes the same files as `sliceform design -o folder`, designing first if needed
        (after a reopen the design is not in memory)."""
        angle = float(obj.FoldAngle.Value) if fold_angle is None else fold_angle
        return self.ensure_design(obj).write_files(folder, angle)


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


def mesh_size():
    """mm, the longest side of a mesh source unless given: the schema's (the CLI's) size."""
    return float(parameters.spec("size")["default"])


def makeSliceform(source, doc=None, **properties):
    """Adds a Sliceform feature for `source` (any shape-bearing object or a mesh), sets
    the preferred defaults (Size 150 for a mesh, which carries no unit) and then the given
    properties, recomputes it and makes its children. Returns it."""
    doc = doc or source.Document
    if shapes.is_mesh(source) and "Size" not in properties:
        properties["Size"] = mesh_size()  # a mesh carries no unit: the CLI's default size
    obj = doc.addObject("Part::FeaturePython", "Sliceform")
    Sliceform(obj)
    obj.Source = source
    obj.Label = "{} sliceform".format(source.Label)
    for name, value in dict(preferred_properties(), **properties).items():
        setattr(obj, name, value)
    if FreeCAD.GuiUp:
        from sliceform_gui import view_provider

        view_provider.ViewProviderSliceform(obj.ViewObject)
    with observer.held():
        doc.recompute()
        syncing.sync(obj)
    return obj
