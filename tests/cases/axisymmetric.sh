#!/usr/bin/env bash
# Axisymmetric wedge mesh (OpenFOAM convention) upgraded to 9/3 elements:
# thick-walled cylinder under internal pressure, plane strain along the axis
# (u_z = 0 top and bottom). Lame solution (e.g. Timoshenko & Goodier):
#   u_r(r) = (1+nu) p a^2 / (E (b^2 - a^2)) [ (1 - 2 nu) r + b^2/r ]
#   axial force on an end = nu (sigma_r + sigma_theta) pi (b^2 - a^2)
#                         = 2 nu p a^2 pi         (full ring)
. "$(dirname "$0")/testFunctions"
lame() { awk -v E="$1" -v nu="$2" -v r="$3" 'BEGIN { p = 1; a = 1; b = 2;
    printf "%.12g", (1 + nu)*p*a*a/(E*(b*b - a*a))*((1 - 2*nu)*r + b*b/r) }'; }

c=$(mktemp -d "${TMPDIR:-/tmp}/formFoamAxi.XXXXXX")
cp -r "$(dirname "$0")/axisymmetricCylinder/." "$c/"
run() { rm -rf "$c/postProcessing"; (cd "$c" && blockMesh -region solid > log.blockMesh 2>&1 && formFoam > log.formFoam 2>&1); }

# 1. dead radial traction p = 1 on the inner surface, nu = 0.3
run || fail "axisymmetric run (see $c/log.formFoam)"
checkClose "u_r(a), traction, nu 0.3" "$(summaryValue "$c" innerRadialDisplacement)" "$(lame 1000 0.3 1)" 1e-5
checkClose "u_r(b), traction, nu 0.3" "$(summaryValue "$c" outerRadialDisplacement)" "$(lame 1000 0.3 2)" 1e-5
checkClose "axial end force 2 nu p pi a^2" "$(summaryValue "$c" axialReaction)" \
    "$(awk 'BEGIN { printf "%.12g", 2*0.3*atan2(0, -1) }')" 1e-5

# 1b. the same with the two wedge patches listed in the other order: the
#    axis (and so the sign of axial results) must not depend on it
sed -i -e '/back   { type wedge/{h;d}' -e '/front  { type wedge/{G}' "$c/system/solid/blockMeshDict"
run || fail "axisymmetric run, wedge patches swapped (see $c/log.formFoam)"
checkClose "axial end force with the wedge patches swapped" "$(summaryValue "$c" axialReaction)" \
    "$(awk 'BEGIN { printf "%.12g", 2*0.3*atan2(0, -1) }')" 1e-5

# 2. nearly incompressible (nu = 0.4999) with a follower pressure on the
#    inner surface (stiff material: the geometry change is ~1e-6)
sed -i 's/E 1000; nu 0.3;/E 1e6; nu 0.4999;/' "$c/constant/solid/solidProperties"
sed -i 's|inner   { type traction; traction (1 0 0); }.*|inner   { type pressure; pressure 1; }|' "$c/0/solid/D"
sed -i 's/linearSolver    cholmod;/linearSolver    auto;/' "$c/system/solidSolution"
run || fail "axisymmetric pressure run (see $c/log.formFoam)"
checkClose "u_r(a), pressure, nu 0.4999" "$(summaryValue "$c" innerRadialDisplacement)" "$(lame 1e6 0.4999 1)" 1e-4
checkClose "u_r(b), pressure, nu 0.4999" "$(summaryValue "$c" outerRadialDisplacement)" "$(lame 1e6 0.4999 2)" 1e-4
if grep -q "linear solver: umfpack" "$c/log.formFoam"; then
    pass "auto picks umfpack for the unsymmetric follower-pressure tangent"
else
    fail "auto did not pick umfpack with a follower pressure"
fi
rm -rf "$c"
