# SPDX-License-Identifier: LGPL-2.1-or-later
"""The assembly steps of a design, from its report: the patches in assembly order, each with
the partners already placed that its slots go onto, and which way each slot opens. The
same steps as instructions.pdf (the core's output/instructions), for FreeCAD's Assembly
steps command."""


def steps(report):
    """[(patch id, text)] in assembly order."""
    placed = set()
    out = []
    for number, pid in enumerate(report["assembly_order"], start=1):
        ways = {"up": [], "down": [], "through": [], "none": []}
        for h in report["hinges"]:
            if pid not in (h["a"], h["b"]):
                continue
            partner, slot = (h["b"], h["slot_a"]) if h["a"] == pid else (h["a"], h["slot_b"])
            if partner in placed and partner not in ways[slot]:
                ways[slot].append(partner)
        said = []
        if number == 1:
            said.append("hold it upright; the next patches slide onto it")
        if ways["up"]:
            said.append("slots opening at the top onto " + ", ".join(ways["up"]))
        if ways["down"]:
            said.append("slots opening at the bottom onto " + ", ".join(ways["down"]))
        if ways["through"]:
            said.append("slots through, onto " + ", ".join(ways["through"]))
        if ways["none"]:
            said.append("uncut where " + ", ".join(ways["none"]) + " is cut through")
        out.append((pid, "Step {} of {}: {}: {}.".format(number, len(report["assembly_order"]), pid, "; ".join(said))))
        placed.add(pid)
    return out
