#!/usr/bin/env python3
"""Writes blockMeshDict: the Turek & Hron (2006) channel around the cylinder
with its flag (CFD1, CSM/FSI geometry), 19 blocks. Usage:
    blockMeshDict.py [refinement factor, default 1]
The cylinder (centre (0.2, 0.2), r 0.05) sits in an O-grid of five blocks in
the box [0.1, 0.3]^2; the flag (x from the cylinder to 0.6, y 0.19-0.21) is
a hole in the mesh; the rest is a grid of blocks with breaks at
x = 0, 0.1, 0.3, 0.6, 2.5 and y = 0, 0.1, 0.19, 0.21, 0.3, 0.41."""
import math
import sys

f = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
n = lambda k: max(1, int(round(k*f)))
na, nr, n4, nfl, ny0, ny4, nx0, nx2, nx3 = \
    n(16), n(10), n(8), n(4), n(8), n(9), n(8), n(24), n(60)
cx, cy, r = 0.2, 0.2, 0.05
depth = 0.01
ya = math.sqrt(r*r - 0.01**2)          # flag attachment x offset

pts = []
index = {}
def P(name, x, y):
    index[name] = len(pts)
    pts.append((x, y))
def pol(a):
    return cx + r*math.cos(math.radians(a)), cy + r*math.sin(math.radians(a))

xs = [0, 0.1, 0.3, 0.6, 2.5]
ys = [0, 0.1, 0.19, 0.21, 0.3, 0.41]
for i, x in enumerate(xs):
    for j, y in enumerate(ys):
        P('g%d%d' % (i, j), x, y)
P('c45', *pol(45)); P('c135', *pol(135)); P('c225', *pol(225))
P('c315', *pol(315))
P('at', cx + ya, 0.21); P('ab', cx + ya, 0.19)

nP = len(pts)
def hexa(a, b, c, d, cells, grading='1 1 1'):
    """Block from the 2D corners a b c d (first direction a -> b, second
    a -> d); turned over (b a d c) if they run clockwise, so that the
    block is right-handed with z the third direction."""
    (ax, ay), (bx, by), (dx, dy) = pts[index[a]], pts[index[b]], pts[index[d]]
    if (bx - ax)*(dy - ay) - (by - ay)*(dx - ax) < 0:
        a, b, c, d = b, a, d, c
    v = [index[k] for k in (a, b, c, d)]
    return 'hex (%s %s) (%s) simpleGrading (%s)' % (
        ' '.join(map(str, v)), ' '.join(str(k + nP) for k in v),
        ' '.join(map(str, cells)), grading)

g = lambda i, j: 'g%d%d' % (i, j)
rg = 0.25  # radial grading: cells at the cylinder 4x thinner than at the box
blocks = [
    # column 0: x 0 - 0.1
    hexa(g(0, 0), g(1, 0), g(1, 1), g(0, 1), (nx0, ny0, 1)),
    hexa(g(0, 1), g(1, 1), g(1, 4), g(0, 4), (nx0, na, 1)),
    hexa(g(0, 4), g(1, 4), g(1, 5), g(0, 5), (nx0, ny4, 1)),
    # column 1: below and above the cylinder box
    hexa(g(1, 0), g(2, 0), g(2, 1), g(1, 1), (na, ny0, 1)),
    hexa(g(1, 4), g(2, 4), g(2, 5), g(1, 5), (na, ny4, 1)),
    # O-grid around the cylinder (first direction along the arc, second
    # outward: grading rg... outward means cells grow away from the wall)
    hexa('c135', 'c225', g(1, 1), g(1, 4), (na, nr, 1), '1 %g 1' % (1/rg)),
    hexa('c225', 'c315', g(2, 1), g(1, 1), (na, nr, 1), '1 %g 1' % (1/rg)),
    hexa('c45', 'c135', g(1, 4), g(2, 4), (na, nr, 1), '1 %g 1' % (1/rg)),
    hexa('at', 'c45', g(2, 4), g(2, 3), (n4, nr, 1), '1 %g 1' % (1/rg)),
    hexa('c315', 'ab', g(2, 2), g(2, 1), (n4, nr, 1), '1 %g 1' % (1/rg)),
    # column 2: x 0.3 - 0.6 (the flag row is solid)
    hexa(g(2, 0), g(3, 0), g(3, 1), g(2, 1), (nx2, ny0, 1)),
    hexa(g(2, 1), g(3, 1), g(3, 2), g(2, 2), (nx2, n4, 1)),
    hexa(g(2, 3), g(3, 3), g(3, 4), g(2, 4), (nx2, n4, 1)),
    hexa(g(2, 4), g(3, 4), g(3, 5), g(2, 5), (nx2, ny4, 1)),
] + [
    # column 3: the wake, x 0.6 - 2.5, cells growing downstream
    hexa(g(3, j), g(4, j), g(4, j + 1), g(3, j + 1), (nx3, ny, 1), '6 1 1')
    for j, ny in enumerate((ny0, n4, nfl, n4, ny4))
]

def arc(a, b, angle):
    x, y = pol(angle)
    out = []
    for z in (0, depth):
        off = 0 if z == 0 else nP
        out.append('arc %d %d (%.10g %.10g %g)' % (index[a] + off, index[b] + off, x, y, z))
    return out
aat = math.degrees(math.atan2(0.01, ya))
edges = (arc('c135', 'c225', 180) + arc('c225', 'c315', 270)
         + arc('c45', 'c135', 90) + arc('at', 'c45', (aat + 45)/2)
         + arc('c315', 'ab', (315 - aat + 360)/2))

def face(*names):
    v = [index[k] for k in names]
    return '(%d %d %d %d)' % (v[0], v[1], v[1] + nP, v[0] + nP)

patches = {
    'inlet': ('patch', [face(g(0, 1), g(0, 0)), face(g(0, 4), g(0, 1)),
                        face(g(0, 5), g(0, 4))]),
    'outlet': ('patch', [face(g(4, j), g(4, j + 1)) for j in range(5)]),
    'walls': ('wall', [face(g(i, 0), g(i + 1, 0)) for i in range(4)]
              + [face(g(i + 1, 5), g(i, 5)) for i in range(4)]),
    'cylinder': ('wall', [face('c225', 'c135'), face('c315', 'c225'),
                          face('c135', 'c45'), face('c45', 'at'),
                          face('ab', 'c315')]),
    'flag': ('wall', [face(g(2, 3), 'at'), face('ab', g(2, 2)),
                      face(g(3, 3), g(2, 3)), face(g(2, 2), g(3, 2)),
                      face(g(3, 2), g(3, 3))]),
}

out = ['FoamFile\n{\n    version     2.0;\n    format      ascii;\n'
       '    class       dictionary;\n    object      blockMeshDict;\n}\n',
       '// Written by blockMeshDict.py %g (refinement factor)\n' % f,
       'vertices\n(']
for z in (0, depth):
    out += ['    (%.10g %.10g %g)' % (x, y, z) for x, y in pts]
out += [');', 'blocks\n(']
out += ['    ' + b for b in blocks]
out += [');', 'edges\n(']
out += ['    ' + e for e in edges]
out += [');', 'boundary\n(']
for name, (typ, faces) in patches.items():
    out.append('    %s { type %s; faces (%s); }' % (name, typ, ' '.join(faces)))
out.append('    frontAndBack { type empty; faces (); }')
out += [');', 'defaultPatch { name frontAndBack; type empty; }']
open(sys.argv[2] if len(sys.argv) > 2 else 'system/fluid/blockMeshDict',
     'w').write('\n'.join(out) + '\n')
