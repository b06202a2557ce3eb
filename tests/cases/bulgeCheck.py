#!/usr/bin/env python3
"""Independent checks of a hydraulic bulge run (tests/cases/hydraulicBulge.sh).

bulgeCheck.py <case> membrane <height>
    At the written time whose pole height is nearest <height>: the pole's
    thickness t and mid-surface radius of curvature rho (least-squares
    circle through the mid-surface points with r < 8 mm) from the VTK
    file, the pressure p from postProcessing/history.dat. Prints
    "sigmaMembrane sigmaSwift h": the membrane stress p rho / (2 t) + p/2
    (equal-biaxial von Mises stress with the mean through-thickness stress
    -p/2) and the Swift flow stress at eps = ln(t0/t) (equal-biaxial
    plastic strain at the pole), K eps0 n from constant/blank/
    solidProperties.

bulgeCheck.py <case> volume
    At the last written time: the volume swept by the blank's lower face
    (axisymmetric, trapezoidal rule over its nodes: sum pi (r1^2 - r0^2)
    (z0 + z1)/2) and the volume the fluid must have taken,
    (V0 + V_inj) exp(-p/K) - V0, with V0, K from constant/oil/
    fluidProperties and p, V_inj from history.dat. Prints "swept expected".
"""
import math, os, re, subprocess, sys

case, what = sys.argv[1], sys.argv[2]

def dictValue(entry, path):
    out = subprocess.run(['foamDictionary', '-entry', entry, '-value',
                          os.path.join(case, path)],
                         capture_output=True, text=True, check=True).stdout
    return out.split()

def nodes(vtu):
    text = open(os.path.join(case, 'VTK', vtu)).read()
    P = [float(v) for v in re.search(
        r'<Points><DataArray[^>]*>(.*?)</DataArray>', text, re.S).group(1).split()]
    D = [float(v) for v in re.search(
        r'Name="displacement"[^>]*>(.*?)</DataArray>', text, re.S).group(1).split()]
    return [(P[3*i], P[3*i + 1], P[3*i] + D[3*i], P[3*i + 1] + D[3*i + 1])
            for i in range(len(P)//3)]

lines = open(os.path.join(case, 'postProcessing', 'history.dat')).read().splitlines()
head = lines[0].split()[1:]
rows = {float(l.split()[0]): [float(v) for v in l.split()] for l in lines[1:]}
col = {n: i for i, n in enumerate(head)}
files = re.findall(r'timestep="([^"]+)" file="([^"]+)"',
                   open(os.path.join(case, 'VTK', 'blank.pvd')).read())

def at(t):
    return rows[min(rows, key=lambda s: abs(s - t))]

if what == 'membrane':
    target = float(sys.argv[3])
    t, f = min(files, key=lambda tf: abs(at(float(tf[0]))[col['poleHeight']] - target))
    row = at(float(t))
    p, h = row[col['pressure']], row[col['poleHeight']]
    N = nodes(f)
    t0 = max(Y for X, Y, x, y in N) - min(Y for X, Y, x, y in N)
    top = {round(X, 6): (x, y) for X, Y, x, y in N if abs(Y - t0) < 1e-9}
    bot = {round(X, 6): (x, y) for X, Y, x, y in N if abs(Y) < 1e-9}
    thick = top[0.0][1] - bot[0.0][1]
    # circle through the mid-surface points near the pole, centre on the
    # axis (r = 0, z = c): minimise sum (r^2 + (z - c)^2 - R^2)^2, linear in
    # c and R^2 - c^2
    pts = [((top[X][0] + bot[X][0])/2, (top[X][1] + bot[X][1])/2)
           for X in top if X in bot and X < 8]
    # r^2 + z^2 = 2 c z + (R^2 - c^2): least squares in (c, k)
    Szz = sum(z*z for r, z in pts); Sz = sum(z for r, z in pts); n = len(pts)
    Sbz = sum((r*r + z*z)*z for r, z in pts); Sb = sum(r*r + z*z for r, z in pts)
    det = 2*Szz*n - 2*Sz*Sz
    c = (Sbz*n - Sb*Sz)/det
    k = (2*Szz*Sb - 2*Sz*Sbz)/det
    rho = math.sqrt(k + c*c)
    K = float(dictValue('material/hardening/K', 'constant/blank/solidProperties')[0])
    e0 = float(dictValue('material/hardening/eps0', 'constant/blank/solidProperties')[0])
    nn = float(dictValue('material/hardening/n', 'constant/blank/solidProperties')[0])
    sigmaM = p*rho/(2*thick) + p/2
    sigmaS = K*(e0 + math.log(t0/thick))**nn
    print('%.6g %.6g %.6g %.6g %.6g' % (sigmaM, sigmaS, h, rho, thick))
elif what == 'volume':
    t, f = files[-1]
    row = at(float(t))
    p, inj = row[col['pressure']], row[col['injected']]
    bot = sorted((X, x, y) for X, Y, x, y in nodes(f) if abs(Y) < 1e-9)
    swept = sum(math.pi*(b[1]**2 - a[1]**2)*(a[2] + b[2])/2
                for a, b in zip(bot, bot[1:]))
    V0 = float(dictValue('initialVolume', 'constant/oil/fluidProperties')[0])
    Kf = float(dictValue('bulkModulus', 'constant/oil/fluidProperties')[0])
    print('%.10g %.10g' % (swept, (V0 + inj)*math.exp(-p/Kf) - V0))
