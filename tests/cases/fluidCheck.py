#!/usr/bin/env python3
"""Checks of the ALE fluid's test cases against exact solutions.

Reads the cell fields an OpenFOAM case wrote (ASCII) and compares them with
the exact solution; the meshes are single blocks of blockMesh, so cell
(i, j) is cell i + n_i j and its centre follows from the block's geometry.

  fluidCheck.py channel CASE TIME NX NY L H UMEAN X
      Plane Poiseuille flow: the velocity profile of the cell column at
      x = X against u = 6 Umean y (H - y)/H^2; prints the largest error
      relative to 1.5 Umean.
  fluidCheck.py pipe CASE TIME NX NR L R DP MU
      Hagen-Poiseuille flow (wedge mesh, x axial): the profile of the
      middle cell column against u = DP/(4 MU L) (R^2 - r^2), r the
      radius of the cell centroid; prints the largest error relative to
      the axis velocity.
  fluidCheck.py radial CASE TIME NR R1 R2 RHO C
      Radial outflow u_r = C/r: p(r) - p(r_mid) against
      RHO C^2/2 (1/r_mid^2 - 1/r^2) over the cells away from the inlet and
      outlet (a third of the cells at either end is left out: the
      zeroGradient outlet drops the viscous normal stress, a constant
      offset); prints the largest error relative to the exact pressure
      range, and the largest radial velocity error relative to C/R1.
  fluidCheck.py uniform CASE UX UY
      Every written time: the largest |U - (UX, UY)| and |p| in the
      fluid region 'water'; prints both (space conservation).
  fluidCheck.py moved CASE TIME
      The largest distance between the points of TIME and of constant.
"""
import math
import os
import re
import sys


def read_field(path):
    text = open(path).read()
    m = re.search(r'internalField\s+uniform\s+(\([^)]*\)|\S+);', text)
    if m:
        return 'uniform', m.group(1)
    m = re.search(r'internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(', text)
    if not m:
        sys.exit('fluidCheck: no internalField in ' + path)
    kind, n = m.group(1), int(m.group(2))
    body = text[m.end():]
    if kind == 'vector':
        vals = re.findall(r'\(([^()]*)\)', body)[:n]
        return 'list', [tuple(float(x) for x in v.split()) for v in vals]
    vals = body.split(')')[0].split()[:n]
    return 'list', [float(x) for x in vals]


def values(path, n):
    kind, v = read_field(path)
    if kind == 'uniform':
        if v.startswith('('):
            t = tuple(float(x) for x in v.strip('()').split())
            return [t]*n
        return [float(v)]*n
    return v


def read_points(path):
    text = open(path).read()
    m = re.search(r'^\s*(\d+)\s*\(', text, re.M)
    n = int(m.group(1))
    vals = re.findall(r'\(([-0-9.eE+ ]+)\)', text[m.end():])[:n]
    return [tuple(float(x) for x in v.split()) for v in vals]


def centroid_radius(a, b):
    """Centroid radius of a thin wedge cell between radii a and b."""
    return 2.0/3.0*(b**3 - a**3)/(b**2 - a**2)


def channel(case, time, nx, ny, L, H, Umean, X):
    nx, ny = int(nx), int(ny)
    L, H, Umean, X = map(float, (L, H, Umean, X))
    U = values(os.path.join(case, time, 'water', 'U'), nx*ny)
    i = int(X/L*nx)
    err = 0.0
    for j in range(ny):
        y = (j + 0.5)*H/ny
        exact = 6*Umean*y*(H - y)/H**2
        err = max(err, abs(U[i + nx*j][0] - exact))
    print('%.6e' % (err/(1.5*Umean)))


def pipe(case, time, nx, nr, L, R, dp, mu):
    nx, nr = int(nx), int(nr)
    L, R, dp, mu = map(float, (L, R, dp, mu))
    U = values(os.path.join(case, time, 'water', 'U'), nx*nr)
    i = nx//2
    umax = dp/(4*mu*L)*R**2
    err = 0.0
    for j in range(nr):
        r = centroid_radius(j*R/nr, (j + 1)*R/nr)
        exact = dp/(4*mu*L)*(R**2 - r**2)
        err = max(err, abs(U[i + nx*j][0] - exact))
    print('%.6e' % (err/umax))


def radial(case, time, nr, r1, r2, rho, c):
    nr = int(nr)
    r1, r2, rho, c = map(float, (r1, r2, rho, c))
    n = 2*nr
    p = values(os.path.join(case, time, 'water', 'p'), n)
    U = values(os.path.join(case, time, 'water', 'U'), n)
    dr = (r2 - r1)/nr
    rc = [centroid_radius(r1 + i*dr, r1 + (i + 1)*dr) for i in range(nr)]
    mid = nr//2
    exact = lambda r: rho*c*c/2*(1/rc[mid]**2 - 1/r**2)
    span = abs(exact(rc[nr//3]) - exact(rc[nr - 1 - nr//3]))
    perr = 0.0
    uerr = 0.0
    for j in range(2):
        for i in range(nr//3, nr - nr//3):
            k = i + nr*j
            perr = max(perr, abs(p[k] - p[mid + nr*j] - exact(rc[i])))
        for i in range(nr):
            ur = math.hypot(U[i + nr*j][1], U[i + nr*j][2])
            uerr = max(uerr, abs(ur - c/rc[i]))
    print('%.6e %.6e' % (perr/span, uerr/(c/r1)))


def uniform(case, ux, uy):
    ux, uy = float(ux), float(uy)
    du = dp = 0.0
    times = [d for d in os.listdir(case)
             if re.fullmatch(r'[0-9.eE+-]+', d) and float(d) > 0]
    if not times:
        sys.exit('fluidCheck: no time directories in ' + case)
    for t in times:
        U = values(os.path.join(case, t, 'water', 'U'), 1)
        p = values(os.path.join(case, t, 'water', 'p'), 1)
        for u in U:
            du = max(du, math.hypot(u[0] - ux, u[1] - uy))
        for v in p:
            dp = max(dp, abs(v))
    print('%.6e %.6e %d' % (du, dp, len(times)))


def moved(case, time):
    a = read_points(os.path.join(case, 'constant', 'water', 'polyMesh',
                                 'points'))
    b = read_points(os.path.join(case, time, 'water', 'polyMesh', 'points'))
    print('%.6e' % max(math.dist(p, q) for p, q in zip(a, b)))


if __name__ == '__main__':
    cmd, args = sys.argv[1], sys.argv[2:]
    {'channel': channel, 'pipe': pipe, 'radial': radial,
     'uniform': uniform, 'moved': moved}[cmd](*args)
