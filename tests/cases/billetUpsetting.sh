#!/usr/bin/env bash
# Billet upsetting (tutorials/billetUpsetting) at reduced size: the 3D
# solver with rigid-tool contact and plasticity against the code's own
# axisymmetric model (BENCHMARKS.md: no closed form with friction and
# barrelling), on the tutorial's coarsest study level (tutorial README,
# Allstudy): the 3D eighth with n+nr+nz = 2+2+4 Hex27P4 against the
# axisymmetric 4 x 6 Q9P3, the whole stroke to half height.
# 1. 3D = axisymmetric within 1 % in the die force and the bulge radius at
#    half height (the tutorial's claim on its own meshes; the difference
#    on this mesh is 0.4 % and 0.1 %).
# 2. Equilibrium: the die force equals the reaction of the mid-plane.
# 3. The slab estimate (BENCHMARKS.md) p = sigma_y (1 + 2 mu r / 3 h) on
#    the mean radius r = R sqrt(2) of the upset billet, sigma_y at
#    eps = ln 2, a sanity check: within 10 % (barrelling reduces the die
#    contact area: the model is below it).
# 4. Newton in 3D: quadratic at the end of the steps (observed order,
#    median, at least 1.8), at most 4 iterations per step on average.
# 5. The square billet (squareSection, 2 x 2 x 4 Hex27P4): a state that no
#    2D model gives, symmetric about the diagonal plane x = y to solver
#    tolerance (the mesh is; the equation numbering is not); its corner
#    bulges less than the faces, and the top corner ends on the die.
# 6. Bad input: two pairs with the same tool and the same patch.
. "$(dirname "$0")/testFunctions"
here=$(cd "$(dirname "$0")" && pwd)
tut=$here/../../tutorials/billetUpsetting
work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamBillet.XXXXXX")

# copyTutorial <sub case or .> <dir> <edits...>: a clean copy, edited, run
copyTutorial()
{
    local src=$1 dir=$2; shift 2
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$tut/$src/0" "$tut/$src/constant" "$tut/$src/system" "$dir/"
    rm -rf "$dir/constant/billet/polyMesh"
    (
        cd "$dir" || exit 1
        for e in "$@"; do eval "$e"; done
        blockMesh -region billet > log.blockMesh 2>&1 \
            || { echo "blockMesh failed"; exit 1; }
        formFoam > log.formFoam 2>&1
    )
}

# 1-4: the round billet
axi=$work/axi
copyTutorial axisymmetric "$axi" \
    "sed -i 's/^nr .*/nr      4;/; s/^nz .*/nz      6;/' system/billet/blockMeshDict" \
    || fail "axisymmetric run (see $axi/log.formFoam)"
c=$work/round
copyTutorial . "$c" \
    "sed -i 's/^n  .*/n       2;/; s/^nr .*/nr      2;/; s/^nz .*/nz      4;/' system/billet/blockMeshDict" \
    "sed -i 's/^\(    maxRadiusAtHalfHeight.*\)/\1\n    midPlaneReaction { type reaction; patch midPlane; component z; scale 4; }/' system/solidSolution" \
    || fail "3D run (see $c/log.formFoam)"
F=$(summaryValue "$c" dieForceAtHalfHeight)
R=$(summaryValue "$c" maxRadiusAtHalfHeight)
checkClose "round billet: 3D die force = axisymmetric" "$F" \
    "$(summaryValue "$axi" dieForceAtHalfHeight)" 0.01
checkClose "round billet: 3D bulge radius = axisymmetric" "$R" \
    "$(summaryValue "$axi" maxRadiusAtHalfHeight)" 0.01
checkClose "round billet: die force = mid-plane reaction" \
    "$(summaryValue "$c" midPlaneReaction)" "$F" 1e-6
# slab estimate: sigma_y(ln 2), r = 10 sqrt(2), h = 15 (the whole billet)
slab=$(calc "565.32*(0.007117 + log(2))^0.2589*(1 + 2*0.1*10*sqrt(2)/(3*15))*3.14159265358979*200")
checkClose "round billet: slab estimate $slab N (sanity)" "$F" "$slab" 0.1
order=$(newtonOrder "$c/log.formFoam")
checkBelow "round billet: Newton quadratic (observed order $order >= 1.8)" 1.8 "$order"
checkBelow "round billet: Newton iterations per step" \
    "$(summaryValue "$c" newtonIterationsPerStep)" 4

# 5. The square billet
s=$work/square
copyTutorial squareSection "$s" \
    "sed -i 's/^n  .*/n       2;/; s/^nz .*/nz      4;/' system/billet/blockMeshDict" \
    "sed -i 's/^\(    maxHalfWidthAtHalfHeight.*\)/\1\n    maxHalfWidthY { type extent; patch side; component y; }\n    cornerY { type position; point (10 10 0); component y; }\n    topCornerY { type position; point (10 10 15); component y; }/' system/solidSolution" \
    || fail "square billet run (see $s/log.formFoam)"
W=$(summaryValue "$s" maxHalfWidthAtHalfHeight)
C=$(summaryValue "$s" cornerAtHalfHeight)
checkClose "square billet: symmetric about x = y, side faces' bulge" \
    "$(summaryValue "$s" maxHalfWidthY)" "$W" 1e-7
checkClose "square billet: symmetric about x = y, corner" \
    "$(summaryValue "$s" cornerY)" "$C" 1e-7
checkClose "square billet: symmetric about x = y, top corner" \
    "$(summaryValue "$s" topCornerY)" "$(summaryValue "$s" topCornerX)" 1e-7
checkBetween "square billet: the corner bulges less than the faces (C - 10 < W - 10)" \
    "$(calc "($C - 10)/($W - 10)")" 0.5 0.99
checkClose "square billet: the top corner is on the die (z = 7.5)" \
    "$(summaryValue "$s" topCornerZ)" 7.5 1e-5

# 6. The same patch in two pairs with one tool
b=$work/twice
copyTutorial squareSection "$b" \
    "sed -i 's/^    sideDie .*/    sideDie { patch top; tool die; friction 0.1; }/' constant/contactProperties"
rc=$?
expectFailure "bad input: a patch in two pairs with the same tool" $rc \
    "$b/log.formFoam" "pair 'sideDie': every node of patch 'top' already belongs to another pair with tool 'die'"

rm -rf "$work"
