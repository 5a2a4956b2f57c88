# SPDX-License-Identifier: LGPL-2.1-or-later
"""Triangle meshes for the benchmark: read OBJ/OFF/STL, midpoint subdivision, OFF writer,
and an icosphere for the smoke run (so CI needs no model files)."""
import math
import struct


def _weld(faces):
    # STL repeats every vertex per facet; weld on exact coordinates so the mesh stays closed.
    index, verts, tris = {}, [], []
    for f in faces:
        tri = []
        for p in f:
            if p not in index:
                index[p] = len(verts)
                verts.append(p)
            tri.append(index[p])
        tris.append(tuple(tri))
    return verts, tris


def _read_stl(path):
    data = open(path, "rb").read()
    n = struct.unpack_from("<I", data, 80)[0] if len(data) >= 84 else -1
    if len(data) == 84 + 50 * n:  # binary: a header, a count, 50 bytes per facet
        faces = [tuple(struct.unpack_from("<3f", data, 84 + 50 * i + 12 + 12 * k) for k in range(3))
                 for i in range(n)]
    else:
        pts = [tuple(float(x) for x in line.split()[1:4])
               for line in data.decode("ascii", "replace").splitlines() if line.strip().startswith("vertex")]
        faces = [tuple(pts[i:i + 3]) for i in range(0, len(pts), 3)]
    return _weld(faces)


def read_mesh(path):
    """(vertices, triangles) of an OBJ, OFF or STL file; polygons are fanned into triangles."""
    lower = path.lower()
    if lower.endswith(".stl"):
        return _read_stl(path)
    verts, polys = [], []
    if lower.endswith(".obj"):
        for line in open(path):
            parts = line.split()
            if parts and parts[0] == "v":
                verts.append(tuple(float(x) for x in parts[1:4]))
            elif parts and parts[0] == "f":
                polys.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    elif lower.endswith(".off"):
        tokens = [line.split("#")[0].split() for line in open(path)]
        tokens = [t for line in tokens for t in line][1:]
        nv, nf = int(tokens[0]), int(tokens[1])
        pos = 3
        for _ in range(nv):
            verts.append(tuple(float(x) for x in tokens[pos:pos + 3]))
            pos += 3
        for _ in range(nf):
            k = int(tokens[pos])
            polys.append([int(x) for x in tokens[pos + 1:pos + 1 + k]])
            pos += 1 + k
    else:
        raise ValueError("not a mesh file: " + path)
    tris = [(p[0], p[i], p[i + 1]) for p in polys for i in range(1, len(p) - 1)]
    return verts, tris


def subdivide(verts, tris):
    """Each triangle into four at its edge midpoints; midpoints are shared, so a closed mesh
    stays closed and the shape does not change (only the triangle count)."""
    verts = list(verts)
    mid = {}

    def m(a, b):
        key = (a, b) if a < b else (b, a)
        if key not in mid:
            mid[key] = len(verts)
            verts.append(tuple((x + y) / 2 for x, y in zip(verts[a], verts[b])))
        return mid[key]

    out = []
    for a, b, c in tris:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return verts, out


def write_off(path, verts, tris):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(verts), len(tris)))
        f.writelines("%.9g %.9g %.9g\n" % v for v in verts)
        f.writelines("3 %d %d %d\n" % t for t in tris)


def icosphere(levels, radius=1.0):
    """A closed sphere: an icosahedron subdivided `levels` times, projected onto the sphere."""
    t = (1 + 5 ** 0.5) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
            (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
            (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        verts, tris = subdivide(verts, tris)
    verts = [tuple(radius * x / math.sqrt(sum(y * y for y in v)) for x in v) for v in verts]
    return verts, tris
