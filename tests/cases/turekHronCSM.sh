#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Body forces and the St. Venant-Kirchhoff material:
#   - a bar hanging under its own weight (tests/cases/hangingBar): linear
#     elasticity, nu = 0, the exact quadratic displacement
#     u_y = -rho g (L^2 - s^2)/(2 E) (s from the free end) at the tip and
#     the middle, and the support's reaction rho g L w (the weight);
#   - Turek & Hron (2006) CSM1 (tests/cases/turekHronCSM1): the elastic
#     flag behind the cylinder under gravity 2, St. Venant-Kirchhoff,
#     static; tip displacement against the benchmark's ux = -7.187 mm,
#     uy = -66.10 mm (BENCHMARKS.md) within 2 % on 20 x 2 elements, the
#     error falls with the mesh (10 x 1, 20 x 2, 40 x 4), Newton quadratic;
#   - bad input: a body force without a density.
#------------------------------------------------------------------------------
cd "$(dirname "$0")" || exit 1
. ./testFunctions
here=$(pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamCSM.XXXXXX")

# runSolid <case> <copy> [edits...]: copy, mesh, run
runSolid() { runCopy "$1" "$2" flag "${@:3}"; }

#- Hanging bar
runSolid hangingBar "$work/bar"
if grep -q '^End' "$work/bar/log.formFoam"; then
    checkClose "hanging bar: tip" "$(summaryValue "$work/bar" tipY)" -5e-3 1e-9
    checkClose "hanging bar: middle" "$(summaryValue "$work/bar" middleY)" -3.75e-3 1e-9
    checkClose "hanging bar: reaction = weight" "$(summaryValue "$work/bar" reaction)" 1 1e-9
else
    fail "hanging bar: formFoam failed"; tail -20 "$work/bar/log.formFoam"
fi

#- CSM1 on three meshes
for m in "10 1" "20 2" "40 4"; do
    set -- $m
    runSolid turekHronCSM1 "$work/csm$1" \
        "sed -i 's/^nx .*/nx $1;/; s/^ny .*/ny $2;/' system/flag/blockMeshDict"
    grep -q '^End' "$work/csm$1/log.formFoam" \
        || { fail "CSM1 $1 x $2: formFoam failed"; tail -20 "$work/csm$1/log.formFoam"; }
done
ux=$(summaryValue "$work/csm20" tipX); uy=$(summaryValue "$work/csm20" tipY)
checkClose "CSM1 20 x 2: ux(A) vs -7.187 mm" "$ux" -7.187e-3 0.02
checkClose "CSM1 20 x 2: uy(A) vs -66.10 mm" "$uy" -66.10e-3 0.02
e10=$(awk -v u="$(summaryValue "$work/csm10" tipY)" 'BEGIN { d = u + 66.10e-3; print d < 0 ? -d : d }')
e20=$(awk -v u="$uy" 'BEGIN { d = u + 66.10e-3; print d < 0 ? -d : d }')
e40=$(awk -v u="$(summaryValue "$work/csm40" tipY)" 'BEGIN { d = u + 66.10e-3; print d < 0 ? -d : d }')
echo "CSM1 uy(A) errors (m): 10 x 1 $e10, 20 x 2 $e20, 40 x 4 $e40"
checkBelow "CSM1: the uy error falls from 10 x 1 to 20 x 2" "$e20" "$e10"
checkBelow "CSM1: 40 x 4 within 0.5 % of the benchmark" "$e40" 3.3e-4
checkClose "CSM1: clamp reaction = weight (rho g 0.35 x 0.02, less the arc)" \
    "$(summaryValue "$work/csm20" clampReaction)" 14 0.01
q=$(newtonOrder "$work/csm20/log.formFoam")
checkBelow "CSM1: Newton order $q (2 - q)" "$(awk -v q="$q" 'BEGIN { print 2 - q }')" 0.3

#- Bad input
base=$work/base
rm -rf "$base"; mkdir -p "$base"; cp -r "$here/hangingBar/." "$base/"
(cd "$base" && blockMesh -region flag > /dev/null 2>&1)
tryCase "body force without a density" \
    "Entry 'bodyForce' in constant/flag/solidProperties needs the density" \
    "sed -i '/rho/d' constant/flag/solidProperties"

rm -rf "$work"
