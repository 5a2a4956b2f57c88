#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Whether every face of a design's assembly (its assembly.brep) passes OCCT's BRepCheck,
as a CAD program reading the STEP file would check it: prints {"faces": n, "invalid":
[[index, why], ...]} as JSON. bench/sweep.py runs it on every design that builds. Uses
FreeCAD's Part module (scripts/setup installs FreeCAD); exit 2 when it cannot be loaded.

    /usr/bin/python3 bench/faces_valid.py out/model/assembly.brep
"""
import json
import sys

for lib in ("/usr/lib/freecad-python3/lib", "/usr/lib/freecad/lib"):
    if lib not in sys.path:
        sys.path.append(lib)
try:
    import FreeCAD  # noqa: F401  (Part needs it loaded first)
    import Part
except ImportError as e:
    sys.exit("faces_valid: FreeCAD's Part module is needed to check the faces (%s)" % e)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: faces_valid.py ASSEMBLY.brep")
    shape = Part.Shape()
    try:
        shape.read(sys.argv[1])
    except Exception as e:  # FreeCAD raises its own Base.FreeCADError
        sys.exit("faces_valid: cannot read %s: %s" % (sys.argv[1], e))
    invalid = []
    for k, face in enumerate(shape.Faces):
        if not face.isValid():
            try:
                face.check(True)
                why = "invalid"
            except Exception as e:  # check() raises with BRepCheck's messages
                why = " ".join(str(e).split())[:200]
            invalid.append([k, why])
    print(json.dumps({"faces": len(shape.Faces), "invalid": invalid}))


if __name__ == "__main__":
    main()
