#!/usr/bin/env bash
# The solid solver in 3D through the case layer (issue 21): a 1 x 1 x 3
# neo-Hookean block of Hex27P4 elements meshed by blockMesh (block3D).
#   1. Rigid motion: the bottom face turned by 120 degrees about (1 1 1)
#      and translated by (1 2 3) in 10 steps carries the free block along
#      rigidly; the rotation maps (x y z) to (z x y), so the far corner
#      (1 1 3) ends at (4 3 4) exactly, with no reaction.
#   2. Follower pressure: symmetry planes x = 0, y = 0, z = 0 and a
#      pressure p on the other faces compress the block uniformly, u =
#      (lambda - 1) X with the Cauchy stress -p I: the corner stays on the
#      diagonal (x = y = z/3) and the bottom reaction is p times the
#      current area lambda^2.
#   3. Restart in 3D with plastic history: a torsion of the top face
#      (elastoPlastic, Swift hardening) restarted from t = 0.5 ends where
#      the uninterrupted run ends.
#   4. Dead traction along z on the top face, linear elastic: the exact
#      uniaxial state.
. "$(dirname "$0")/testFunctions"

work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamSolid3D.XXXXXX")

# 1. Rigid motion about an oblique axis
c=$work/rigid
runCopy block3D "$c" block || fail "rigid motion run (see $c/log.formFoam)"
# Exact to the force tolerance: 1e-8 of the load level leaves the corner
# of the 1 x 1 x 3 column about 1e-10 (relative) from its exact place
# through the column's bending stiffness (observed 1.5e-10 since the
# tracked pressure ends each step one iteration earlier; 1e-11 before)
checkClose "rigid motion: corner x" "$(summaryValue "$c" cornerX)" 4 1e-9
checkClose "rigid motion: corner y" "$(summaryValue "$c" cornerY)" 3 1e-9
checkClose "rigid motion: corner z" "$(summaryValue "$c" cornerZ)" 4 1e-9
checkClose "rigid motion: top face extent z" "$(summaryValue "$c" topZMax)" 4 1e-9
checkClose "rigid motion: corner displacement along (1 1 1) (summary direction)" \
    "$(summaryValue "$c" cornerDiagonal)" 3.46410161513775 1e-9
r=$(summaryValue "$c" bottomReactionZ)
checkBelow "rigid motion: no reaction (|$r| < 1e-9 E)" "$(calc "abs($r)")" 1e-6

# 2. Follower pressure on three faces, symmetry planes on the others
p=50
c=$work/pressure
runCopy block3D "$c" block \
    "sed -i '/^    bottom /,/translation/d' 0/block/D" \
    "sed -i 's/^    xMin .*/    xMin { type fixedDisplacement; components (x); }\n    bottom { type fixedDisplacement; components (z); }/' 0/block/D" \
    "sed -i 's/^    yMin .*/    yMin { type fixedDisplacement; components (y); }/' 0/block/D" \
    "sed -i 's/^    \(xMax\|yMax\|top\) .*/    \1 { type pressure; pressure table ((0 0) (1 $p)); }/' 0/block/D" \
    || fail "pressure run (see $c/log.formFoam)"
x=$(summaryValue "$c" cornerX)
checkBelow "pressure: compressed (corner x = $x < 0.99)" "$x" 0.99
checkClose "pressure: homogeneous, corner y = x" "$(summaryValue "$c" cornerY)" "$x" 1e-9
checkClose "pressure: homogeneous, corner z = 3 x" "$(summaryValue "$c" cornerZ)" "$(calc "3*$x")" 1e-9
checkClose "pressure: bottom reaction = p lambda^2 (follower load)" \
    "$(summaryValue "$c" bottomReactionZ)" "$(calc "$p*$x*$x")" 1e-9
# ... the same with symmetryPlane patches on a solid (non-shell) region
#     (they hold no rotations there: a region without shell nodes once
#     stopped on "constraint component 4 out of range")
c=$work/pressureSymmetry
runCopy block3D "$c" block \
    "sed -i '/^    bottom /,/translation/d' 0/block/D" \
    "sed -i 's/^    xMin .*/    xMin { type symmetryPlane; normal (1 0 0); }\n    bottom { type symmetryPlane; normal (0 0 1); }/' 0/block/D" \
    "sed -i 's/^    yMin .*/    yMin { type symmetryPlane; normal (0 1 0); }/' 0/block/D" \
    "sed -i 's/^    \(xMax\|yMax\|top\) .*/    \1 { type pressure; pressure table ((0 0) (1 $p)); }/' 0/block/D" \
    || fail "pressure run with symmetry planes (see $c/log.formFoam)"
checkClose "pressure: symmetryPlane patches as fixed components" "$(summaryValue "$c" cornerX)" "$x" 1e-12

# 3. Torsion of a plastic block, restarted at t = 0.5
torsion=(
    "sed -i 's/type        neoHookean;/type elastoPlastic; hardening { type swift; K 5; eps0 0.01; n 0.2; }/' constant/block/solidProperties"
    "sed -i '/^    bottom /,/translation/d' 0/block/D"
    "sed -i 's/^    xMin .*/    xMin { type free; }\n    bottom { type fixedDisplacement; }/' 0/block/D"
    "sed -i 's/^    top .*/    top { type rigidMotion; origin (0.5 0.5 3); axis (0 0 1); angle table ((0 0) (1 0.3)); translation table ((0 (0 0 0)) (1 (0 0 0.05))); }/' 0/block/D"
)
c=$work/torsion
runCopy block3D "$c" block "${torsion[@]}" || fail "torsion run (see $c/log.formFoam)"
# largest equivalent plastic strain of the cells at t = 1
epsMax=$(awk '/^internalField/ { f = 1; next } f && /^\(/ { inList = 1; next }
    inList && /^\)/ { exit } inList { if ($1 > m) m = $1 } END { print m + 0 }' \
    "$c/1/block/epsilonEq")
checkBelow "torsion: plastic (largest epsilonEq $epsMax > 0.01)" 0.01 "$epsMax"
declare -A full
for e in cornerX cornerY cornerZ bottomReactionZ; do full[$e]=$(summaryValue "$c" $e); done
rm -rf "$c/1" "$c/postProcessing/summary"
sed -i 's/^startFrom .*/startFrom       latestTime;/' "$c/system/controlDict"
(cd "$c" && timeout 300 formFoam > log.restart 2>&1) || fail "torsion restart (see $c/log.restart)"
grep -q "Restarting from the state written at time 0.5" "$c/log.restart" \
    && pass "torsion: restarted from t = 0.5" \
    || fail "torsion: restart did not start from t = 0.5 (see $c/log.restart)"
for e in cornerX cornerY cornerZ bottomReactionZ; do
    checkClose "torsion restarted at 0.5: $e as uninterrupted" \
        "$(summaryValue "$c" $e)" "${full[$e]}" 1e-9
done

# 4. Dead traction through the case layer: linear elastic, symmetry planes
#    x = 0, y = 0, z = 0 and a traction sigma = 5 along z on the top: the
#    uniaxial state, exact in the element space: u_z(top) = sigma L/E,
#    u_x(x = 1) = -nu sigma/E, and the reaction balances sigma * 1 * 1
c=$work/traction
runCopy block3D "$c" block \
    "sed -i 's/type        neoHookean;/type        linearElastic;/' constant/block/solidProperties" \
    "sed -i '/^    bottom /,/translation/d' 0/block/D" \
    "sed -i 's/^    xMin .*/    xMin { type fixedDisplacement; components (x); }\n    bottom { type fixedDisplacement; components (z); }/' 0/block/D" \
    "sed -i 's/^    yMin .*/    yMin { type fixedDisplacement; components (y); }/' 0/block/D" \
    "sed -i 's/^    top .*/    top { type traction; traction table ((0 (0 0 0)) (1 (0 0 5))); }/' 0/block/D" \
    || fail "traction run (see $c/log.formFoam)"
checkClose "traction: u_z(top) = sigma L/E" "$(summaryValue "$c" cornerZ)" "$(calc "3 + 5*3/1000")" 1e-12
checkClose "traction: u_x(x = 1) = -nu sigma/E" "$(summaryValue "$c" cornerX)" "$(calc "1 - 0.3*5/1000")" 1e-12
checkClose "traction: bottom reaction = -sigma A" "$(summaryValue "$c" bottomReactionZ)" -5 1e-9
rm -rf "$work"
