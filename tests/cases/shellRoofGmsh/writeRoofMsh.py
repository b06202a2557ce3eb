#!/usr/bin/env python3
"""The mid-surface of the Scordelis-Lo roof's quarter (tutorials/
shellBenchmarks/scordelisLo: the cylinder R = 25 about the x axis, x in
[0, 25], phi in [0, 40 deg] from the crown, z up) as a Gmsh surface mesh,
written as Gmsh writes MSH 4.1 or 2.2 (ASCII): n x n quadrangles (or each
cut into two triangles), nodes uniform in x and phi (where the blockMesh
roof's arcs put them), element normals outward (away from the axis);
physical curves midspan (x = 0), diaphragm (x = 25), crown (phi = 0),
freeEdge (phi = 40 deg), physical surface roof. For gmshToFormFoam -shell
(tests/cases/meshes.sh).

    writeRoofMsh.py out.msh [--version 4.1|2.2] [--n 16] [--triangles]
                    [--bad mixed|branch|fold|interiorCurve]

--bad writes inputs the converter must refuse: one quadrangle cut into
triangles (mixed), a third element on an interior edge (branch), a flap
folded back by 120 deg along the free edge (fold), a physical curve on an
interior edge (interiorCurve).
"""
import argparse
import math

p = argparse.ArgumentParser()
p.add_argument("out")
p.add_argument("--version", default="4.1")
p.add_argument("--n", type=int, default=16)
p.add_argument("--triangles", action="store_true")
p.add_argument("--bad", choices=["mixed", "branch", "fold", "interiorCurve"])
a = p.parse_args()
n = a.n
R, L, phiMax = 25.0, 25.0, math.radians(40)


def nid(i, j):
    return 1 + i + (n + 1) * j


nodes = {}
for j in range(n + 1):
    for i in range(n + 1):
        phi = phiMax * j / n
        nodes[nid(i, j)] = (L * i / n, R * math.sin(phi), R * math.cos(phi))

surface = []        # (gmsh type, nodes)
for j in range(n):
    for i in range(n):
        q = [nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)]
        if a.triangles or (a.bad == "mixed" and i == j == 0):
            if (i + j) % 2 == 0:
                surface += [(2, [q[0], q[1], q[2]]), (2, [q[0], q[2], q[3]])]
            else:
                surface += [(2, [q[0], q[1], q[3]]), (2, [q[1], q[2], q[3]])]
        else:
            surface.append((3, q))
curves = {
    "midspan": [[nid(0, j), nid(0, j + 1)] for j in range(n)],
    "diaphragm": [[nid(n, j), nid(n, j + 1)] for j in range(n)],
    "crown": [[nid(i, 0), nid(i + 1, 0)] for i in range(n)],
    "freeEdge": [[nid(i, n), nid(i + 1, n)] for i in range(n)],
}

extra = max(nodes) + 1
if a.bad == "branch":
    # a fin on the interior edge (i = 1, j = 1)-(i = 2, j = 1), outward
    b, c = nid(1, 1), nid(2, 1)
    for k in (b, c):
        x, y, z = nodes[k]
        r = math.hypot(y, z)
        nodes[extra] = (x, y * (r + 2) / r, z * (r + 2) / r)
        extra += 1
    surface.append((3, [b, c, extra - 1, extra - 2]))
if a.bad == "fold":
    # flaps along the free edge, turned back by 120 deg from the surface
    phi = phiMax
    ePhi = (0, math.cos(phi), -math.sin(phi))
    inward = (0, -math.sin(phi), -math.cos(phi))
    d = [2 * (math.cos(math.radians(120)) * ePhi[k]
              + math.sin(math.radians(120)) * inward[k]) for k in range(3)]
    first = extra
    for i in range(n + 1):
        x, y, z = nodes[nid(i, n)]
        nodes[extra] = (x + d[0], y + d[1], z + d[2])
        extra += 1
    for i in range(n):
        surface.append((3, [nid(i + 1, n), nid(i, n), first + i, first + i + 1]))
if a.bad == "interiorCurve":
    curves["crown"].append([nid(1, 1), nid(2, 1)])

names = list(curves)
out = ["$MeshFormat", "%s 0 8" % a.version, "$EndMeshFormat"]
out += ["$PhysicalNames", str(len(names) + 1)]
out += ['1 %d "%s"' % (k + 1, s) for k, s in enumerate(names)]
out += ['2 1 "roof"', "$EndPhysicalNames"]
if a.version.startswith("2"):
    out += ["$Nodes", str(len(nodes))]
    out += ["%d %.17g %.17g %.17g" % (k, *v) for k, v in nodes.items()]
    out += ["$EndNodes"]
    elems = [(1, k + 1, e) for k, s in enumerate(names) for e in curves[s]]
    elems += [(t, 1, e) for t, e in surface]
    out += ["$Elements", str(len(elems))]
    out += ["%d %d 2 %d %d %s" % (k + 1, t, ph, ph, " ".join(map(str, e)))
            for k, (t, ph, e) in enumerate(elems)]
    out += ["$EndElements"]
else:
    # curves 1..4 and surface 1, one entity per physical group
    out += ["$Entities", "0 %d 1 0" % len(names)]
    out += ["%d 0 0 0 1 1 1 1 %d 0" % (k + 1, k + 1) for k in range(len(names))]
    out += ["1 0 0 0 1 1 1 1 1 0", "$EndEntities"]
    out += ["$Nodes", "1 %d 1 %d" % (len(nodes), max(nodes)), "2 1 0 %d" % len(nodes)]
    out += [str(k) for k in nodes]
    out += ["%.17g %.17g %.17g" % v for v in nodes.values()]
    out += ["$EndNodes"]
    blocks, tag = [], 1
    for k, s in enumerate(names):
        blocks.append("1 %d 1 %d" % (k + 1, len(curves[s])))
        for e in curves[s]:
            blocks.append("%d %s" % (tag, " ".join(map(str, e))))
            tag += 1
    for t in (3, 2):
        els = [e for tt, e in surface if tt == t]
        if not els:
            continue
        blocks.append("2 1 %d %d" % (t, len(els)))
        for e in els:
            blocks.append("%d %s" % (tag, " ".join(map(str, e))))
            tag += 1
    nBlocks = len(names) + len({t for t, _ in surface})
    out += ["$Elements", "%d %d 1 %d" % (nBlocks, tag - 1, tag - 1)]
    out += blocks + ["$EndElements"]
with open(a.out, "w") as f:
    f.write("\n".join(out) + "\n")
