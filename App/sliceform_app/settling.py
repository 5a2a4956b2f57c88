# SPDX-License-Identifier: LGPL-2.1-or-later
"""TechDraw's views while they draw. FreeCAD 1.0 computes a view's hidden lines, then its
faces, in Qt's global thread pool and finishes the job in the view when the result arrives
through the event loop; a view removed meanwhile gets that call with no name in the document
and throws (std::logic_error through the event loop: headless, a crashed interpreter). So a
view is removed only once it is known to draw nothing: settled, or recomputed from an empty
source since (DrawViewPart::execute then returns before starting a thread). And a view
recomputed while it still finds hidden lines returns at once: it keeps what that pass finds
for good, so one recomputed then with other sources is recomputed again once the views
settled. FreeCAD 0.20 draws inside the recompute: nothing is ever left drawing."""
import time

import FreeCAD

# Only FreeCAD 1.0 draws in threads, and draws an empty source without complaint (0.20
# marks that view invalid).
THREADED = BLANK_LEFT_OVERS = tuple(int(x) for x in FreeCAD.Version()[:2]) >= (1, 0)

# The views that may still be drawing, (document name, view name) -> what their sources gave
# them when they began (_given): recomputed with something to draw, or restored with the
# document, since the views last settled. A Slices edit on fandisk removes one or two
# engraving views whose parts are no longer needed; waiting for every view of the edit
# before that took 0.16-0.22 s of FreeCAD 1.0's 0.74 s.
_drawing = {}
# Views recomputed, while they may still have been drawing, with sources that give something
# else (DrawViewPart::execute returns at once then): a Margin edit right after the sliceform
# was made left 726 of a page's 727 DXF lines where the layout before had them, after any
# wait. They are recomputed again once every view settled. What the sources give decides,
# not that the view was recomputed: a Margin edit on the box recomputes 104 of its 130 views
# twice (their drawings change, then the sync moves them), with the same sources.
_stale = set()
_timer = None
_UNKNOWN = object()  # what sources the sliceform did not make gave, or a restored view drew


def empty(shape):
    return shape.isNull() or not shape.SubShapes


def _blank(source):
    """Whether the source gives a view nothing to draw. Its Shape is read only where its
    proxy says it was emptied (children._left_over): reading a Shape copies it (FreeCAD 1.0
    copies its element map too, 0.5 ms a sheet drawing), and the shape, not the hint, decides
    (an Undo gives an emptied drawing its shape back and leaves the proxy as it was)."""
    return getattr(getattr(source, "Proxy", None), "blank", False) and empty(source.Shape)


def _given(view):
    """What the view's sources give it, without reading a Shape: a sheet drawing's proxy
    says what it was last built from (`built`: the design, patch and part) and whether it was
    emptied. _UNKNOWN where a source is not a sheet drawing."""
    given = []
    for source in view.Source:
        proxy = getattr(source, "Proxy", None)
        if getattr(proxy, "Type", None) not in ("SliceformSheetPatch", "SliceformEngraving"):
            return _UNKNOWN
        given.append((source.Name, getattr(proxy, "built", None), getattr(proxy, "blank", False)))
    return tuple(given)


def view_recomputed(view):
    """The document observer's report of a recomputed view."""
    key = (view.Document.Name, view.Name)
    if key in _drawing:
        # It goes on drawing what it began with: an empty source too leaves the old patch.
        given = _given(view)
        if THREADED and (given is _UNKNOWN or given != _drawing[key]):
            _stale.add(key)
        return
    _stale.discard(key)  # drawn afresh, from what its sources give now
    if not all(_blank(source) for source in view.Source):
        _add([view], _given)


def views_restored(views):
    """Views of a document being opened: FreeCAD draws them without a recompute."""
    _add(views, lambda view: _UNKNOWN)


def may_be_drawing(views):
    return any((v.Document.Name, v.Name) in _drawing for v in views)


def _add(views, given):
    for v in views:
        _drawing.setdefault((v.Document.Name, v.Name), given(v))
    if FreeCAD.GuiUp and _drawing:
        _watch()


def _settled():
    """Every view drew what it was last given: none counts as drawing any more. Those
    recomputed while they still drew are recomputed now (and draw again), unless a document
    is recomputing or being opened (Qt's loop turns inside a recompute, for its progress
    bar): then they stay stale until the views next settle. Returns whether none was
    recomputed."""
    _drawing.clear()
    if any(d.Recomputing or d.Restoring for d in FreeCAD.listDocuments().values()):
        if _stale and FreeCAD.GuiUp:
            _watch()
        return True
    views = [v for v in (_view(doc, name) for doc, name in sorted(_stale)) if v is not None]
    _stale.clear()
    for view in views:
        view.touch()
        view.recompute()
    _add(views, _given)
    return not views


def _forget():
    _drawing.clear()
    _stale.clear()


def _view(doc_name, name):
    doc = FreeCAD.listDocuments().get(doc_name)
    return doc.getObject(name) if doc is not None else None


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
                _timer.stop()
                _settled()  # watches again if it recomputed a view

        _timer.timeout.connect(check)
    _timer.idle = 0
    _timer.start()


def settle_views(seconds=60):
    """Lets every TechDraw view finish what its threads are doing (see above). FreeCAD 0.20
    returns at once. User input is not processed while waiting."""
    try:
        from PySide import QtCore
    except ImportError:
        return _forget()
    app = QtCore.QCoreApplication.instance()
    if app is None:  # no event loop to deliver a result: nothing draws in threads
        return _forget()
    pool = QtCore.QThreadPool.globalInstance()
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        pool.waitForDone(100)
        # A finished hidden-line pass starts face finding: loop until both are delivered.
        app.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents)
        if pool.activeThreadCount() == 0:
            app.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents)
            if pool.activeThreadCount() == 0 and _settled():
                return
