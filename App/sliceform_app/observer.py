# SPDX-License-Identifier: LGPL-2.1-or-later
"""The document recompute: a sliceform recomputed inside an edit's transaction gets its
children synced (syncing.py) before the transaction closes, as part of the same Undo step."""
import FreeCAD

from sliceform_app import lookup, settling


class _Observer:
    """Follows every document recompute: a sliceform recomputed inside a transaction (a
    property edited in the property editor, a command) gets its children synced just
    before that transaction closes, so what changes is part of the same Undo step. Outside
    any transaction (a script with Undo off) they are synced right after the recompute."""

    def __init__(self):
        self.busy = False
        self.pending = set()  # (document, sliceform) names recomputed and not synced yet

    def slotRecomputedObject(self, obj):
        if lookup.proxy_type(obj) == "Sliceform":
            self.pending.add((obj.Document.Name, obj.Name))
        elif obj.TypeId == "TechDraw::DrawViewPart":
            settling.view_recomputed(obj)

    def slotRecomputedDocument(self, doc):
        from sliceform_app import feature

        feature.restore_traceback()
        if getattr(doc, "HasPendingTransaction", False):
            return  # synced before the transaction closes
        # No transaction: nothing to keep in one Undo step. No recompute can run inside
        # this one: the GUI syncs as soon as it is over; without it, the new children are
        # built one by one now and stay marked for the next recompute.
        if FreeCAD.GuiUp:
            from PySide import QtCore

            name = doc.Name
            QtCore.QTimer.singleShot(0, lambda: self._sync(lambda d: d == name, recompute=True))
        else:
            self._sync(lambda d: d == doc.Name, recompute=False)

    def slotBeforeCloseTransaction(self, abort):
        if abort:
            self.pending.clear()  # the document goes back to what it was
        else:
            self._sync(lambda d: True, recompute=True)

    def _sync(self, which, recompute):
        from sliceform_app import syncing

        if self.busy:
            return
        names = [(d, n) for d, n in self.pending if which(d)]
        self.pending.difference_update(names)
        self.busy = True
        try:
            for d, n in names:
                doc = FreeCAD.listDocuments().get(d)
                obj = doc.getObject(n) if doc is not None else None
                if obj is None or getattr(doc, "Transacting", False) or not lookup.is_sliceform(obj):
                    continue
                try:
                    syncing.sync(obj, recompute)
                except Exception as e:  # never break the user's edit
                    FreeCAD.Console.PrintError("Sliceform: {}\n".format(e))
        finally:
            self.busy = False


_observer = None


class held:
    """with held(): doc.recompute(); sync(obj) -- the caller syncs, the observer waits."""

    def __enter__(self):
        self.was = _observer.busy if _observer else False
        self.pending = set(_observer.pending) if _observer else set()
        if _observer:
            _observer.busy = True

    def __exit__(self, *exc):
        if _observer:
            _observer.busy = self.was
            _observer.pending = self.pending


def synced(doc_name, name):
    """A sync of that sliceform has begun: the observer need not sync it again."""
    if _observer is not None:
        _observer.pending.discard((doc_name, name))


def install_observer():
    global _observer
    if _observer is None:
        _observer = _Observer()
        FreeCAD.addDocumentObserver(_observer)
