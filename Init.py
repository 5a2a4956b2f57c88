# SPDX-License-Identifier: LGPL-2.1-or-later
# Sliceform, run by FreeCAD at start-up with or without GUI. It only puts the addon's two
# Python packages (App/sliceform_app, Gui/sliceform_gui) on sys.path; nothing is imported
# until used, so a missing compiled module cannot stop FreeCAD from starting.
import os
import sys


def _sliceform_add_paths():
    # FreeCAD exec()s this file without __file__, after putting the addon folder on
    # sys.path: find that folder by what it contains.
    for base in list(sys.path):
        if os.path.isfile(os.path.join(base, "App", "sliceform_app", "__init__.py")):
            for sub in ("App", "Gui"):
                path = os.path.join(base, sub)
                if path not in sys.path:
                    sys.path.append(path)
            return


_sliceform_add_paths()
