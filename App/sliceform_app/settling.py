# SPDX-License-Identifier: LGPL-2.1-or-later
"""TechDraw's views while they draw. FreeCAD 1.0 computes a view's hidden lines, then its
faces, in Qt's global thread pool and finishes the job in the view when the result arrives
through the event loop; a view removed meanwhile gets that call with no name in the document
and throws (std::logic_error through the event loop: headless, a crashed interpreter). So a
view is removed only once it is known to draw nothing: settled, or recomputed from an empty
source since (DrawViewPart::execute then returns before starting a thread). FreeCAD 0.20
draws inside the recompute: nothing is ever left drawing."""
import time

import FreeCAD

# Only FreeCAD 1.0 draws an empty source without complaint: 0.20 marks that view invalid.
BLANK_LEFT_OVERS = tuple(int(x) for x in FreeCAD.Version()[:2]) >= (1, 0)

# (document name, view name) of the views that may still be drawing: recomputed with
# something to draw, or restored with the document, since the views last settled. A Slices
# edit on fandisk removes one or two engraving views whose parts are no longer needed; waiting
# for every view of the edit before that took 0.16-0.22 s of FreeCAD 1.0's 0.74 s.
_drawing = set()
_timer = None


def empty(shape):
    return shape.isNull() or not shape.SubShapes


def _blank(source):
    """Whether the source gives a view nothing to draw. Its Shape is read only where its
    proxy says it was emptied (children._left_over): reading a Shape copies it (FreeCAD 1.0
    copies its element map too, 0.5 ms a sheet drawing), and the shape, not the hint, decides
    (an Undo gives an emptied drawing its shape back and leaves the proxy as it was)."""
    return getattr(getattr(source, "Proxy", None), "blank", False) and empty(source.Shape)


def view_recomputed(view):
    """The document observer's report of a recomputed view."""
    if not all(_blank(source) for source in view.Source):
        _add([view])


def views_restored(views):
    """Views of a document being opened: FreeCAD draws them without a recompute."""
    _add(views)


def may_be_drawing(views):
    return any((v.Document.Name, v.Name) in _drawing for v in views)


def _add(views):
    _drawing.update((v.Document.Name, v.Name) for v in views)
    if FreeCAD.GuiUp and _drawing:
        _watch()


def _watch():
    """In the GUI, Qt's event loop delivers the views' results itself: the views count as
    settled once the thread pool was idle at two checks in a row with the loop turning
    between them, the test settle_views makes, without blocking."""
    global _timer
    from PySide import QtCore

    if _timer is None:
        _timer = QtCore.QTimer()
        _timer.setInterval(100)

        def check():
            _timer.idle = _timer.idle + 1 if QtCore.QThreadPool.globalInstance().activeThreadCount() == 0 else 0
            if _timer.idle >= 2:
                _drawing.clear()
                _timer.stop()

        _timer.timeout.connect(check)
    _timer.idle = 0
    _timer.start()


def settle_views(seconds=60):
    """Lets every TechDraw view finish what its threads are doing (see above). FreeCAD 0.20
    returns at once. User input is not processed while waiting."""
    try:
        from PySide import QtCore
    except ImportError:
        _drawing.clear()
        return
    app = QtCore.QCoreApplication.instance()
    if app is None:  # no event loop to deliver a result: nothing draws in threads
        _drawing.clear()
        return
    pool = QtCore.QThreadPool.globalInstance()
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        pool.waitForDone(100)
        # A finished hidden-line pass starts face finding: loop until both are delivered.
        app.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents)
        if pool.activeThreadCount() == 0:
            app.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents)
            if pool.activeThreadCount() == 0:
                _drawing.clear()
                return
