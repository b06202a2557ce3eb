#!/usr/bin/env python3
"""Write the 3D quarter ring of tests/cases/ring (a = 1 <= r <= b = 2,
0 <= theta <= 90 deg, 0 <= z <= 1) as a Gmsh mesh of 27-node hexahedra
(nr x nt x 1) with every node on the exact cylinders, in MSH 4.1 or 2.2
ASCII, as Gmsh would write it: physical surfaces inner, outer, bottom,
left, frontAndBack and a physical volume ring. Used by tests/cases/meshes.sh
(no Gmsh needed to run the tests).

    writeRingMsh.py <out.msh> [--version 2.2|4.1] [--nr 2] [--nt 3]
                    [--hex20] [--tet]
--hex20 writes 20-node hexahedra, --tet one tetrahedron instead of the
first hexahedron: inputs gmshToFormFoam must refuse.
"""
import argparse
import math

p = argparse.ArgumentParser()
p.add_argument("out")
p.add_argument("--version", default="4.1")
p.add_argument("--nr", type=int, default=2)
p.add_argument("--nt", type=int, default=3)
p.add_argument("--hex20", action="store_true")
p.add_argument("--tet", action="store_true")
a = p.parse_args()
nr, nt = a.nr, a.nt
NI, NJ, NK = 2 * nr + 1, 2 * nt + 1, 3


def nid(k, l, m):
    return 1 + k + NI * (l + NJ * m)


nodes = {}
for m in range(NK):
    for l in range(NJ):
        for k in range(NI):
            r = 1 + k / (2 * nr)
            t = 0.5 * math.pi * l / (2 * nt)
            nodes[nid(k, l, m)] = (r * math.cos(t), r * math.sin(t), m / 2)

# Gmsh Hexahedron27 node order as corner sets (lattice offsets 0..2)
corner = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0),
          (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
sets = [[0], [1], [2], [3], [4], [5], [6], [7],
        [0, 1], [0, 3], [0, 4], [1, 2], [1, 5], [2, 3],
        [2, 6], [3, 7], [4, 5], [4, 7], [5, 6], [6, 7],
        [0, 1, 2, 3], [0, 1, 5, 4], [0, 3, 7, 4], [1, 2, 6, 5],
        [2, 3, 7, 6], [4, 5, 6, 7], list(range(8))]
offsets = [tuple(sum(corner[c][d] for c in s) // len(s) for d in range(3))
           for s in sets]

hexes = []
for j in range(nt):
    for i in range(nr):
        hexes.append([nid(2 * i + o[0], 2 * j + o[1], o[2]) for o in offsets])
if a.hex20:
    hexes = [h[:20] for h in hexes]
hexType = 17 if a.hex20 else 12
if a.tet:
    tet = hexes[0][:3] + [hexes[0][4]]


def quad9(f):
    """f(u, v) -> node, u, v in 0..2: the 9-node quad (corners, edges,
    centre)"""
    c = [f(0, 0), f(2, 0), f(2, 2), f(0, 2)]
    e = [f(1, 0), f(2, 1), f(1, 2), f(0, 1)]
    return c + e + [f(1, 1)]


surfaces = {"inner": [], "outer": [], "bottom": [], "left": [],
            "frontAndBack": []}
for j in range(nt):
    surfaces["inner"].append(quad9(lambda u, v: nid(0, 2 * j + u, v)))
    surfaces["outer"].append(quad9(lambda u, v: nid(2 * nr, 2 * j + u, v)))
for i in range(nr):
    surfaces["bottom"].append(quad9(lambda u, v: nid(2 * i + u, 0, v)))
    surfaces["left"].append(quad9(lambda u, v: nid(2 * i + u, 2 * nt, v)))
for j in range(nt):
    for i in range(nr):
        for m in (0, 2):
            surfaces["frontAndBack"].append(
                quad9(lambda u, v: nid(2 * i + u, 2 * j + v, m)))

names = list(surfaces)
out = []
out += ["$MeshFormat", "%s 0 8" % a.version, "$EndMeshFormat"]
out += ["$PhysicalNames", str(len(names) + 1)]
out += ['2 %d "%s"' % (k + 1, n) for k, n in enumerate(names)]
out += ['3 %d "ring"' % (len(names) + 1), "$EndPhysicalNames"]
vol = len(names) + 1
if a.version.startswith("2"):
    out += ["$Nodes", str(len(nodes))]
    out += ["%d %.17g %.17g %.17g" % (k, *v) for k, v in nodes.items()]
    out += ["$EndNodes"]
    elems = []
    for k, n in enumerate(names):
        for q in surfaces[n]:
            elems.append((10, k + 1, q))
    for h in hexes:
        elems.append((hexType, vol, h))
    if a.tet:
        elems[-1] = (4, vol, tet)
    out += ["$Elements", str(len(elems))]
    out += ["%d %d 2 %d %d %s" % (e + 1, t, ph, ph, " ".join(map(str, ns)))
            for e, (t, ph, ns) in enumerate(elems)]
    out += ["$EndElements"]
else:
    # one entity per physical group: surfaces 1..5, volume 1
    out += ["$Entities", "0 0 %d 1" % len(names)]
    for k in range(len(names)):
        out += ["%d 0 0 0 1 1 1 1 %d 0" % (k + 1, k + 1)]
    out += ["1 0 0 0 1 1 1 1 %d 0" % vol, "$EndEntities"]
    n = len(nodes)
    out += ["$Nodes", "1 %d 1 %d" % (n, n), "3 1 0 %d" % n]
    out += [str(k) for k in nodes]
    out += ["%.17g %.17g %.17g" % v for v in nodes.values()]
    out += ["$EndNodes"]
    nElem = sum(len(surfaces[s]) for s in names) + len(hexes)
    blocks = []
    tag = 1
    for k, s in enumerate(names):
        lines = []
        for q in surfaces[s]:
            lines.append("%d %s" % (tag, " ".join(map(str, q))))
            tag += 1
        blocks.append("2 %d 10 %d" % (k + 1, len(lines)))
        blocks += lines
    hexLines = []
    for h in hexes:
        hexLines.append("%d %s" % (tag, " ".join(map(str, h))))
        tag += 1
    if a.tet:
        blocks += ["3 1 4 1", "%d %s" % (tag, " ".join(map(str, tet)))]
        hexLines = hexLines[1:]
    blocks += ["3 1 %d %d" % (hexType, len(hexLines))] + hexLines
    nBlocks = len(names) + 1 + (1 if a.tet else 0)
    out += ["$Elements", "%d %d 1 %d" % (nBlocks, nElem, tag - 1)]
    out += blocks + ["$EndElements"]
with open(a.out, "w") as f:
    f.write("\n".join(out) + "\n")
