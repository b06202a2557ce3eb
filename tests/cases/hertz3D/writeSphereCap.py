#!/usr/bin/env python3
"""Write the cap of the sphere of tests/cases/hertz3D (centre (0 0 50),
radius 50) under the block's contact zone as an ASCII STL file: a square
grid of spacing h over [-2, 6] x [-2, 6] in x, y (h divides 2: x = 0 and
y = 0 are grid lines), every point lifted onto the sphere (z = 50 -
sqrt(50^2 - x^2 - y^2)), every square cut into two triangles. The triangles' vertex order makes their normals point out of
the ball (down, towards the block).

    writeSphereCap.py h out.stl
"""
import math
import sys

h, out = float(sys.argv[1]), sys.argv[2]
R, lo, hi = 50.0, -2.0, 6.0
n = int(round((hi - lo)/h))
pts = [[(lo + i*h, lo + j*h, R - math.sqrt(R*R - (lo + i*h)**2 - (lo + j*h)**2))
        for j in range(n + 1)] for i in range(n + 1)]


def facet(f, a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    nrm = [u[1]*v[2] - u[2]*v[1], u[2]*v[0] - u[0]*v[2], u[0]*v[1] - u[1]*v[0]]
    L = math.sqrt(sum(x*x for x in nrm))
    f.write('  facet normal %.9g %.9g %.9g\n    outer loop\n' % tuple(x/L for x in nrm))
    for p in (a, b, c):
        f.write('      vertex %.12g %.12g %.12g\n' % p)
    f.write('    endloop\n  endfacet\n')


with open(out, 'w') as f:
    f.write('solid ball\n')
    for i in range(n):
        for j in range(n):
            p00, p10, p01, p11 = pts[i][j], pts[i + 1][j], pts[i][j + 1], pts[i + 1][j + 1]
            # clockwise seen from above: normals down, out of the ball;
            # the diagonals alternate (a union-jack pattern), so that the
            # facets are symmetric about the planes x = 0 and y = 0 of the
            # quarter model
            if (i + j) % 2 == 0:
                facet(f, p00, p11, p10)
                facet(f, p00, p01, p11)
            else:
                facet(f, p00, p01, p10)
                facet(f, p10, p01, p11)
    f.write('endsolid ball\n')
