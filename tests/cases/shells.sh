#!/usr/bin/env bash
# MITC4 shells through the case layer (issue 22): the mid-surface of a
# sheet meshed one hexahedron thick by blockMesh, symmetry planes and
# diaphragm supports, a dead traction on the sheet's face.
#   1. Scordelis-Lo roof (tutorials/shellBenchmarks/scordelisLo; SHELLS.md:
#      w = -0.3024 at the free edge's midpoint, MacNeal & Harder 1985) on
#      8 x 8, 16 x 16 and 32 x 32 quarter meshes: within 3 %, 1.5 % and
#      0.8 % (observed -2.6 %, -1.1 %, -0.57 %), the change of w falling
#      by more than half with each refinement; MITC4+ on 16 x 16 gives
#      MITC4's w (flat elements, the same linear stiffness).
#   2. A restart of the geometrically nonlinear roof (the full weight,
#      4 steps) from t = 0.5 ends where the uninterrupted run ends: the
#      directors' frames come back from the restart state.
#   3. A square plate (side 2, L/t = 200, nu = 0.3) under a uniform
#      pressure on its top face (a follower load, pushing down), quarter
#      model with symmetry planes (tests/cases/shellPlate); SHELLS.md:
#      the centre's deflection -1.267e-3 p (2L)^4/D clamped, -4.062e-3
#      simply supported (Timoshenko, Kirchhoff plates): clamped 8 x 8 and
#      16 x 16 within 2.5 % and 1 % (observed +2.0 %, +0.72 %), simply
#      supported 16 x 16 within 1 % (+0.71 %; 32 x 32: +0.39 %, +0.23 %).
#      The clamped plate of MITC3+ triangles (a triangulated OBJ surface
#      extruded one prism thick, tests/cases/shellPlateTriangles):
#      8 x 8 x 2 and 16 x 16 x 2 within 3 % and 1 % (observed -2.1 %,
#      -0.57 %), written to VTK as triangles.
#   4. Contact: a plate strip in plane strain (symmetry planes on both
#      sides: every node is a corner of two planes at the span's centre)
#      pressed at the centre of its span L = 100 by a cylindrical punch
#      moved 0.1 into it, on the top face and, mirrored, on the bottom
#      face (tests/cases/shellBending): the centre's mid-surface follows
#      the punch at the half thickness, less the compression of the
#      contact points f h/(E A) = 2.2e-6 of the stroke (1e-7; observed
#      8e-9), the punch force is beam
#      theory's 24 D b w/L^3 = 0.43956 within 0.2 % (observed -0.024 %),
#      and the support's reaction balances it; the director at the
#      support turns by beam theory's 3 w/L = 0.003 within 1 % (summary
#      directorRotation); the thinnest element's
#      current thickness (summary shellThickness) is below the section's
#      by less than 1e-3; the stresses at the bottom, middle and top
#      points are written.
#   5. Bad input stops with a message naming the file and the entry: a
#      negative thickness, 11 points through it, 2 Lobatto points, a shell section for a
#      solid element, shells in a 2D analysis, an oblique symmetry plane,
#      a pressure on the sheet's edge, a line load on its face, an
#      unknown shell element type, MITC3+ on a sheet of hexahedra, a
#      sheet two cells thick.
. "$(dirname "$0")/testFunctions"
ref=-0.3024
work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamShells.XXXXXX")

run()   # run <case>: blockMesh + formFoam, logs in the case
{
    rm -rf "$1/postProcessing"
    (cd "$1" && blockMesh -region roof > log.blockMesh 2>&1 \
             && formFoam > log.formFoam 2>&1)
}

# 1. Mesh convergence
c=$(caseCopy shellBenchmarks/scordelisLo)
declare -A w
for n in 8 16 32; do
    [ $n -eq 8 ] || sed -i "s/^n  *[0-9]*;/n       $n;/" "$c/system/roof/blockMeshDict"
    run "$c" || fail "Scordelis-Lo $n x $n run (see $c/log.formFoam)"
    w[$n]=$(summaryValue "$c" wFreeEdge)
done
checkClose "Scordelis-Lo 8 x 8: free edge w" "${w[8]}" $ref 0.03
checkClose "Scordelis-Lo 16 x 16: free edge w" "${w[16]}" $ref 0.015
checkClose "Scordelis-Lo 32 x 32: free edge w" "${w[32]}" $ref 0.008
# The change with each refinement falls by about 3 (observed 0.34):
# the mesh converges (towards -0.3012, a few tenths of a percent off the
# classical reference, as flat four-node elements do)
checkBelow "Scordelis-Lo: |w32 - w16| < |w16 - w8| / 2" \
    "$(calc 'abs(c - b)/abs(b - a)' a="${w[8]}" b="${w[16]}" c="${w[32]}")" 0.5
# MITC4+ (elementType MITC4+) through the case layer: the roof's
# elements are flat (rectangles inscribed in the cylinder), where MITC4+
# has MITC4's linear stiffness: the same w (observed -1.09 %; Ko et al.
# 2017, Table 10, report 0.9973 for their MITC4+ against 0.9886 for
# MITC4: an open difference, doc/verification.md)
sed -i "s/^n  *[0-9]*;/n       16;/" "$c/system/roof/blockMeshDict"
sed -i 's/^elementType .*/elementType     MITC4+;/' "$c/constant/roof/solidProperties"
run "$c" || fail "Scordelis-Lo MITC4+ 16 x 16 run (see $c/log.formFoam)"
grep -q "MITC4+" "$c/log.formFoam" \
    && pass "Scordelis-Lo: the log names MITC4+" \
    || fail "Scordelis-Lo: the log does not name MITC4+ (see $c/log.formFoam)"
checkClose "Scordelis-Lo MITC4+ 16 x 16: free edge w as MITC4" \
    "$(summaryValue "$c" wFreeEdge)" "${w[16]}" 1e-6
sed -i 's/^elementType .*/elementType     MITC4;/' "$c/constant/roof/solidProperties"

# 2. Restart of the nonlinear roof at t = 0.5
sed -i "s/^n  *[0-9]*;/n       8;/" "$c/system/roof/blockMeshDict"
sed -i 's/traction (0 0 -0.09)/traction (0 0 -90)/' "$c/0/roof/D"
sed -i 's/^deltaT .*/deltaT          0.25;/; s/^writeInterval .*/writeInterval   0.5;/' \
    "$c/system/controlDict"
run "$c" || fail "nonlinear roof run (see $c/log.formFoam)"
full=$(summaryValue "$c" wFreeEdge)
# Under the full weight the shell's geometric nonlinearity shows: w is
# 16 % below the linear response (the summary still scales by 1000)
checkBelow "nonlinear roof: |w/w_linear - 1| > 0.05" \
    0.05 "$(calc 'abs(f/(1000*l) - 1)' f="$full" l="${w[8]}")"
rm -rf "$c/1" "$c/postProcessing/summary"
sed -i 's/^startFrom .*/startFrom       latestTime;/' "$c/system/controlDict"
(cd "$c" && formFoam > log.restart 2>&1) || fail "roof restart (see $c/log.restart)"
grep -q "Restarting from the state written at time 0.5" "$c/log.restart" \
    && pass "roof: restarted from t = 0.5" \
    || fail "roof: restart did not start from t = 0.5 (see $c/log.restart)"
checkClose "roof restarted at 0.5: w as uninterrupted" \
    "$(summaryValue "$c" wFreeEdge)" "$full" 1e-9
rm -rf "$c"

# 3. Plates under pressure (the summary divides by p (2L)^4/D)
c=$work/plate
runCopy shellPlate "$c" plate || fail "clamped plate 8 x 8 run (see $c/log.formFoam)"
checkClose "clamped plate 8 x 8: centre w / (p (2L)^4/D)" \
    "$(summaryValue "$c" wCentre)" -1.267e-3 0.025
runCopy shellPlate "$c" plate \
    "sed -i 's/^n       8;/n       16;/' system/plate/blockMeshDict" \
    || fail "clamped plate 16 x 16 run (see $c/log.formFoam)"
checkClose "clamped plate 16 x 16: centre w / (p (2L)^4/D)" \
    "$(summaryValue "$c" wCentre)" -1.267e-3 0.01
runCopy shellPlate "$c" plate \
    "sed -i 's/^n       8;/n       16;/' system/plate/blockMeshDict" \
    "sed -i 's/{ type clamped; }/{ type fixedDisplacement; components (z); }/' 0/plate/D" \
    || fail "simply supported plate run (see $c/log.formFoam)"
checkClose "simply supported plate 16 x 16: centre w / (p (2L)^4/D)" \
    "$(summaryValue "$c" wCentre)" -4.062e-3 0.01
# MITC3+ triangles: the plate's mid-surface as a triangulated surface (an
# OBJ file), extruded one prism thick by extrudeMesh, its sides split
# into patches by topoSet and createPatch (tests/cases/shellPlateTriangles/
# makeMesh); the triangles' deflection converges from below (observed
# -2.1 %, -0.57 %; 32 x 32 x 2: -0.19 %)
c=$work/plateTriangles
runCopy shellPlateTriangles "$c" "" "./makeMesh 8" \
    || fail "clamped plate of triangles 8 x 8 x 2 run (see $c/log.formFoam)"
w8=$(summaryValue "$c" wCentre)
checkClose "clamped plate MITC3+ 8 x 8 x 2: centre w / (p (2L)^4/D)" "$w8" -1.267e-3 0.03
grep -q '<DataArray type="UInt8" Name="types" format="ascii">' "$c/VTK/plate_0.vtu" \
    && [ "$(grep -A1 'Name="types"' "$c/VTK/plate_0.vtu" | tail -1)" = 5 ] \
    && pass "plate of triangles: VTK triangles (cell type 5) written" \
    || fail "plate of triangles: no VTK triangles in $c/VTK/plate_0.vtu"
# The OpenFOAM cell field D of triangles: each cell its mid-surface
# centre's displacement, the mean of its 3 nodes (the largest within 0.9
# to 1 of the largest nodal deflection: observed 0.973)
ratio=$(python3 - "$c" <<'EOF'
import os, re, sys
c = sys.argv[1]
t = max((d for d in os.listdir(c) if re.fullmatch(r'[0-9.]+', d) and d != '0'), key=float)
def largest(f):
    s = open(os.path.join(c, t, 'plate', f)).read()
    s = s[s.index('List<vector>') if 'List<vector>' in s else s.index('FoamFile'):]
    m = re.search(r'(\d+)\s*\(', s)
    v = re.findall(r'\(([-+0-9.eE]+ [-+0-9.eE]+ [-+0-9.eE]+)\)', s[m.end() - 1:])
    return max(abs(float(x.split()[2])) for x in v[:int(m.group(1))])
print('%.6g' % (largest('D')/largest('feU')))
EOF
)
checkBetween "plate of triangles: largest cell D_z / largest nodal u_z" "$ratio" 0.9 1
runCopy shellPlateTriangles "$c" "" "./makeMesh 16" \
    || fail "clamped plate of triangles 16 x 16 x 2 run (see $c/log.formFoam)"
checkClose "clamped plate MITC3+ 16 x 16 x 2: centre w / (p (2L)^4/D)" \
    "$(summaryValue "$c" wCentre)" -1.267e-3 0.01

# 4. Three-point bending by a punch on either face
beam=0.439560439560   # 24 D b w / L^3, D = 2e5/(12 (1 - 0.09)), b = 10
c=$work/bending
runCopy shellBending "$c" strip || fail "bending, top face (see $c/log.formFoam)"
# The centre follows the punch less the compression of its contact point
# through the half thickness (contactModel.H): each of the 2 nodes under
# the punch (share A = 2.5 of the face) carries half the punch force f,
# and gives way by f (t/2)/(E A)
give() { calc 'abs(f)/2*0.5/(2e5*2.5)' f="$(summaryValue "$c" punchForce)"; }
checkClose "bending, top face: centre follows the punch (less f h/(E A))" "$(summaryValue "$c" wCentre)" "$(calc '-0.1 + g' g="$(give)")" 1e-7
checkClose "bending, top face: punch force vs beam theory" "$(summaryValue "$c" punchForce)" -$beam 2e-3
checkClose "bending, top face: end reaction balances it" \
    "$(summaryValue "$c" endReaction)" "$(calc '-f' f="$(summaryValue "$c" punchForce)")" 1e-8
checkClose "bending, top face: the director's turn at the support vs beam theory 3 w/L" \
    "$(summaryValue "$c" endRotation)" 0.003 0.01
# The current thickness (summary shellThickness) falls below the
# section's 1 where the sheet is stretched (Poisson), by less than 1e-3
t=$(summaryValue "$c" thicknessMin)
checkBelow "bending: thinnest element below the section thickness 1" "$t" 1
checkBelow "bending: and by less than 1e-3" "$(calc '1 - t' t="$t")" 1e-3
last=$(ls -d "$c"/[0-9]* | sort -g | tail -1)
[ -f "$last/strip/sigmaTop" ] && [ -f "$last/strip/sigmaMiddle" ] \
    && [ -f "$last/strip/sigmaBottom" ] && [ -f "$last/strip/thickness" ] \
    && pass "bending: stresses at the bottom, middle and top points written" \
    || fail "bending: no sigmaTop, sigmaMiddle, sigmaBottom, thickness in $last/strip"
runCopy shellBending "$c" strip \
    "sed -i 's/point (0 0 5.5)/point (0 0 -5.5)/; s/(1 (0 0 -0.1))/(1 (0 0 0.1))/; s/patch top;/patch bottom;/' constant/contactProperties" \
    || fail "bending, bottom face (see $c/log.formFoam)"
checkClose "bending, bottom face: centre follows the punch (less f h/(E A))" "$(summaryValue "$c" wCentre)" "$(calc '0.1 - g' g="$(give)")" 1e-7
checkClose "bending, bottom face: punch force vs beam theory" "$(summaryValue "$c" punchForce)" $beam 2e-3

# 5. Bad input
bad()   # bad <label> <regex> <edit>...: the edited roof must fail
{
    local label=$1 regex=$2 d
    shift 2
    d=$(caseCopy shellBenchmarks/scordelisLo)
    (cd "$d" && for e in "$@"; do eval "$e"; done \
        && blockMesh -region roof > log.blockMesh 2>&1)
    (cd "$d" && formFoam > log.formFoam 2>&1)
    expectFailure "$label" $? "$d/log.formFoam" "$regex"
    rm -rf "$d"
}
bad "negative thickness" "shell/thickness.*not a positive thickness" \
    "sed -i 's/thicknessPoints 2;/thicknessPoints 2; thickness -0.25;/' constant/roof/solidProperties"
bad "11 points through the thickness" "shell/thicknessPoints.*valid: 1 to 10" \
    "sed -i 's/thicknessPoints 2;/thicknessPoints 11;/' constant/roof/solidProperties"
bad "2 Lobatto points" "shell/thicknessPoints.*valid: 3 to 10" \
    "sed -i 's/thicknessPoints 2;/thicknessPoints 2; thicknessRule Lobatto;/' constant/roof/solidProperties"
bad "shell section for a solid element" "a shell section, but elementType Hex8" \
    "sed -i 's/^elementType .*/elementType     Hex8;/' constant/roof/solidProperties"
bad "shells in a 2D analysis" "need analysisType solid3D" \
    "sed -i 's/^analysisType .*/analysisType    planeStrain;/' constant/roof/solidProperties"
bad "oblique symmetry plane" "normal.*must be a coordinate axis" \
    "sed -i 's/normal (0 1 0)/normal (0 1 1)/' 0/roof/D"
bad "pressure on the sheet's edge" "freeEdge.*pressures act on the faces of the sheet" \
    "sed -i 's/freeEdge  { type free; }/freeEdge { type pressure; pressure 1; }/' 0/roof/D"
bad "line load on the sheet's face" "line load on 'outer'.*not a side" \
    "sed -i 's/outer     { type traction; traction (0 0 -0.09); }/outer { type lineLoad; lineLoad (0 0 1); }/' 0/roof/D"
bad "unknown shell element" "elementType.*MITC4 MITC4\\+" \
    "sed -i 's/^elementType .*/elementType     MITC4p;/' constant/roof/solidProperties"
bad "point load off the mesh" "Point \\(1 2 3\\).*pointLoads.P.*is not a node.*mid-surface" \
    "sed -i 's/^material/pointLoads { P { point (1 2 3); force (0 0 1); } }\\nmaterial/' constant/roof/solidProperties"
bad "point load with neither force nor moment" "neither 'force' nor 'moment'" \
    "sed -i 's/^material/pointLoads { P { point (0 0 25); } }\\nmaterial/' constant/roof/solidProperties"
bad "point loads as a word" "pointLoads.*must be a dictionary" \
    "sed -i 's/^material/pointLoads none;\\nmaterial/' constant/roof/solidProperties"
bad "line moment on the sheet's face" "line moment on 'outer'.*not a side" \
    "sed -i 's/outer     { type traction; traction (0 0 -0.09); }/outer { type lineMoment; lineMoment (0 1 0); }/' 0/roof/D"
bad "oblique diaphragm" "normal.*a diaphragm's normal must be a coordinate axis" \
    "sed -i 's/diaphragm { type fixedDisplacement; components (y z); }/diaphragm { type diaphragm; normal (1 1 0); }/' 0/roof/D"
bad "pin with an unknown component" "Unknown component .w. in .*solidProperties.pin.A" \
    "sed -i 's/^material/pin { A { point (0 0 25); components (w); } }\\nmaterial/' constant/roof/solidProperties"
bad "MITC3+ on a sheet of hexahedra" "meshed one prism thick .MITC3.: prisms" \
    "sed -i 's/^elementType .*/elementType     MITC3+;/' constant/roof/solidProperties"
bad "sheet two cells thick" "not meshed one cell thick|no two opposite faces" \
    "sed -i 's/(\$n \$n 1)/(\$n \$n 2)/' system/roof/blockMeshDict"
rm -rf "$work"
