#!/usr/bin/env python3
"""The elastica of a strip pressed onto a rigid cylinder (tests/cases/
shellContact.sh, case tests/cases/shellWrap): an independent reference.

shellWrapCheck.py L rho D p
    A strip of length L (per unit width, bending stiffness D, inextensible,
    no transverse shear), symmetric about its point x = 0 on the top line
    of a cylinder, is pressed onto it by a follower pressure p. Where it
    touches, its mid-surface lies on the circle of radius rho and its
    moment is D/rho. The free part [L - l, L] carries the pressure; about
    a point A of it the pressure on the part beyond A (to the tip B) has
    the resultant p R90 (B - A) and the moment p |B - A|^2/2, whatever the
    shape (the pressure on a curve acts as on its chord). So from the tip
    (curvature 0) integrate the free part backwards,
        dr/ds = -(cos psi, sin psi),  dpsi/ds = p |r|^2/(2 D),
    (r from the tip, psi the tangent's angle from the tip's) until the
    moment p |r|^2/2 reaches D/rho: that is the separation point, l the
    free length, and the wrap angle phi = (L - l)/rho. Prints
    "tipX tipZ tipRotation phi l": the tip's position (the cylinder's top
    line at x = z = 0, its axis at z = -rho) and the turn of its director.
    Runge-Kutta 4 with 20000 steps per unit length; the separation point
    by linear interpolation (step error below 1e-9).
"""
import math, sys

L, rho, D, p = map(float, sys.argv[1:5])
Mc = D/rho                         # the wrapped part's moment

def rhs(y):
    x, z, psi = y
    return (-math.cos(psi), -math.sin(psi), p*(x*x + z*z)/(2*D))

h = 1/20000
y, s = (0.0, 0.0, 0.0), 0.0
while True:
    k1 = rhs(y)
    k2 = rhs([a + 0.5*h*b for a, b in zip(y, k1)])
    k3 = rhs([a + 0.5*h*b for a, b in zip(y, k2)])
    k4 = rhs([a + h*b for a, b in zip(y, k3)])
    yn = [a + h/6*(b1 + 2*b2 + 2*b3 + b4)
          for a, b1, b2, b3, b4 in zip(y, k1, k2, k3, k4)]
    m0 = p*(y[0]**2 + y[1]**2)/2
    m1 = p*(yn[0]**2 + yn[1]**2)/2
    if m1 >= Mc:
        f = (Mc - m0)/(m1 - m0)
        y = [a + f*(b - a) for a, b in zip(y, yn)]
        s += f*h
        break
    y, s = yn, s + h
    if s > L:
        sys.exit("shellWrapCheck: the pressure is too low to wrap the strip")

l = s
phi = (L - l)/rho
# Separation point S and its tangent angle -phi; the tip's tangent angle
# alpha = -phi - psi(l) (psi grows backwards, the strip curls down)
Sx, Sz = rho*math.sin(phi), rho*math.cos(phi) - rho
alpha = -phi - y[2]
# r(l) = S - B in the tip's frame: rotate by alpha into the global frame
rx = math.cos(alpha)*y[0] - math.sin(alpha)*y[1]
rz = math.sin(alpha)*y[0] + math.cos(alpha)*y[1]
print("%.10g %.10g %.10g %.10g %.10g" % (Sx - rx, Sz - rz, -alpha, phi, l))
