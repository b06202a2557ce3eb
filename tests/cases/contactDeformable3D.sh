#!/usr/bin/env bash
# Contact of two deformable bodies in 3D (contactModelDeformable3D.C,
# deformableSurface.H): tests/cases/flatPunchDeformable3D, a quarter of an
# elastic punch [0, 10]^2 x [5, 7] on an elastic block [0, 10]^2 x [0, 5]
# (27/4 hexahedra, E = 200000, nu = 0.3, geometrically linear; symmetry
# x = 0 and y = 0, the block's bottom on rollers), the punch's bottom
# nodes against the block's top faces, the punch's top pushed down by
# 0.01. Exact: both bodies in the uniaxial state eps_zz = -0.01/7, the
# force F = E 0.01/7 x 100 = 28571.43 on both ends, the interface
# pressure p = F/A on the current (laterally expanded) area,
# p = E (0.01/7)/(1 + nu 0.01/7)^2.
# 1. Patch test, matching faces (4 x 4 elements on both sides): every
#    contactor node closed, the nodal pressure uniform and exact (1e-6),
#    F exact (1e-8).
# 2. A punch of 8 x 8 (its nodes include all the block's): the same.
# 3. Non-matching faces, single pass: node-to-face contact does not pass
#    the patch test (Taylor & Papadopoulos 1991; Wriggers, Computational
#    Contact Mechanics, 2006, sec. 9.3): the contactor's consistent
#    nodal forces are pressed onto the target's faces at other points. The
#    error is small when the contactor is the finer side: punch 5 x 5 and
#    7 x 7 on the block's 4 x 4: F within 1 % (observed -0.31 %, -0.12 %),
#    equilibrium (punch = bottom reaction, 1e-8); the coarser punch 3 x 3
#    (-4.7 %) shows why the finer side should be the contactor.
# 4. Two-pass (a second pair with the roles swapped), punch 3 x 3: F
#    within 0.1 % (observed -0.013 %).
# 5. Friction, mu = 0.2: the whole punch (no symmetry planes, the block's
#    bottom clamped) pressed down, then dragged by 0.05 at 30 deg to x.
#    Every closed node slides: its tangential force is mu times its normal
#    force (1e-5: the regularised law leaves 1/2 (sqrt(epsT)/s)^2, about
#    3e-6 at these slip rates); the drag needed at the punch's top points along the
#    motion, |drag| = mu N within 1 % (the slip directions and the
#    normals of the sheared block's top scatter a little, and the nodes
#    of the leading edge leave the block: observed -0.17 %), its
#    direction within 1 deg of 30 deg.
# 6. Force control: a rigid plane, force-controlled, presses the punch's
#    top with F = 28571.43 (instead of the prescribed displacement): the
#    uniaxial state again, the top at 7 - 0.01 (1e-7 relative), the bottom
#    reaction F (1e-8): a rigid pair and a deformable pair in one model.
# 7. Newton converges quadratically in every run (at most 8 iterations in
#    a step).
. "$(dirname "$0")/testFunctions"

work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamContactDeformable3D.XXXXXX")
F=28571.4285714286
p=$(calc "200000*(0.01/7)/(1 + 0.3*0.01/7)^2")

# pressureStats <case> <time> <pair>: "nodes closed pmin pmax maxRelError"
pressureStats()
{
    awk -v p="$p" '!/^#/ && NF >= 15 {
        ++n; if ($15 == 1) ++c; e = ($12 - p)/p; if (e < 0) e = -e; if (e > d) d = e
        if (n == 1 || $12 < mn) mn = $12; if (n == 1 || $12 > mx) mx = $12 }
        END { if (n) printf "%d %d %.8g %.8g %.3g\n", n, c, mn, mx, d }' \
        "$1/postProcessing/contact/$2/$3.dat"
}

# newtonChecks <label> <case>: at most 8 iterations in a step
newtonChecks()
{
    local m
    m=$(summaryValue "$2" maxIterationsInAStep)
    checkBetween "$1: at most 8 Newton iterations in a step" "$m" 1 8
}

# punch <nPunch> <label> <pressure tol> <force tol> [two-pass]
punch()
{
    local np=$1 label=$2 ptol=$3 ftol=$4 twoPass=${5:-}
    local c=$work/punch$np$twoPass
    # (the case as stored has nPunch 4: edit only another number)
    local mesh=true
    [ "$np" = 4 ] || mesh="sed -i 's/^nPunch .*/nPunch  $np;/' system/block/blockMeshDict"
    if runCopy flatPunchDeformable3D "$c" block "$mesh" \
        "${twoPass:+sed -i 's/^\( *punchBlock .*\)\$/\1\n    blockPunch { patch blockTop; targetPatch punchBottom; friction 0; }/' constant/contactProperties}"
    then
        local Fp Fb
        Fp=$(summaryValue "$c" punchReaction)
        Fb=$(summaryValue "$c" bottomReaction)
        read -r n closed pmin pmax dev < <(pressureStats "$c" 1 punchBlock)
        echo "    $label (punch $np x $np on 4 x 4): $closed of $n nodes closed," \
             "pressure $pmin .. $pmax (exact $p), F $Fp (exact $F)"
        checkClose "$label: punch reaction = bottom reaction" "$Fb" "$Fp" 1e-8
        checkClose "$label: force" "$Fp" "$F" "$ftol"
        if [ -n "$ptol" ]; then
            [ "${n:-0}" -gt 0 ] && [ "$closed" = "$n" ] \
                && pass "$label: all $n contactor nodes closed" \
                || fail "$label: $closed of $n contactor nodes closed"
            checkBelow "$label: nodal pressure, max relative error" "$dev" "$ptol"
        fi
        newtonChecks "$label" "$c"
    else
        fail "$label run (see $c/log.formFoam)"
    fi
}

punch 4 "matching faces" 1e-6 1e-8
punch 8 "punch nodes include the block's" 1e-6 1e-8
punch 5 "non-matching, finer punch" "" 0.01
punch 7 "non-matching, finer punch" "" 0.01
punch 3 "two-pass, coarser punch" "" 0.001 twoPass

# 5. Friction
c=$work/friction
if runCopy flatPunchDeformable3D "$c" block \
    "sed -i 's/friction 0;/friction 0.2;/' constant/contactProperties" \
    "sed -i 's/^        components (z);/        components (x y z);/' 0/block/D" \
    "sed -i 's/(1 (0 0 -0.01)));/(1 (0 0 -0.01)) (2 (0.04330127 0.025 -0.01)));/' 0/block/D" \
    "sed -i 's/^    xSymmetry .*/    xSymmetry { type free; }/; s/^    ySymmetry .*/    ySymmetry { type free; }/' 0/block/D" \
    "sed -i 's/^    bottom .*/    bottom { type fixedDisplacement; components (x y z); }/' 0/block/D" \
    "sed -i 's/^endTime .*/endTime 2;/' system/controlDict" \
    "sed -i 's/^\( *bottomReaction .*\)\$/\1\n    dragX { type reaction; patch punchTop; component x; }\n    dragY { type reaction; patch punchTop; component y; }/' system/solidSolution"
then
    N=$(summaryValue "$c" punchReaction)
    dx=$(summaryValue "$c" dragX)
    dy=$(summaryValue "$c" dragY)
    read -r nSlide ratioErr < <(awk '!/^#/ && NF >= 15 && $15 == 1 {
        ++n; e = $10/$9/0.2 - 1; if (e < 0) e = -e; if (e > d) d = e }
        END { printf "%d %.3g\n", n, d }' "$c/postProcessing/contact/2/punchBlock.dat")
    drag=$(calc "sqrt(x^2 + y^2)" x="$dx" y="$dy")
    angle=$(calc "atan2(y, x)*180/3.14159265358979" x="$dx" y="$dy")
    echo "    friction: N $N, drag ($dx $dy), |drag|/(mu N) $(calc "d/(0.2*n)" d="$drag" n="$N"), angle $angle deg," \
         "$nSlide closed nodes, max |tau/(mu lambda) - 1| $ratioErr"
    [ "${nSlide:-0}" -gt 0 ] && pass "friction: $nSlide nodes in contact" \
        || fail "friction: no node in contact"
    checkBelow "friction: every closed node slides, tau = mu lambda" "$ratioErr" 1e-5
    checkClose "friction: |drag| = mu N" "$drag" "$(calc "0.2*n" n="$N")" 0.01
    checkClose "friction: drag along the motion (30 deg)" "$angle" 30 0.033
    newtonChecks "friction" "$c"
else
    fail "friction run (see $c/log.formFoam)"
fi

# 6. Force control: a rigid plane on the punch's top
c=$work/forceControl
if runCopy flatPunchDeformable3D "$c" block \
    "sed -i '/^    punchTop$/,/^    }$/d' 0/block/D" \
    "sed -i 's/^    punchBottom .*/    punchTop { type free; }\n&/' 0/block/D" \
    "sed -i 's/^pairs/tools { press { surface { type plane; point (0 0 7.01); normal (0 0 -1); } force table ((0 0) (1 $F)); direction (0 0 -1); } }\n\npairs/' constant/contactProperties" \
    "sed -i 's/^\( *punchBlock .*\)\$/\1\n    press { patch punchTop; tool press; friction 0; }/' constant/contactProperties" \
    "sed -i 's/^    punchReaction .*/    topZ { type position; point (10 10 7); component z; }\n    pressForce { type toolForce; tool press; component z; }/' system/solidSolution"
then
    read -r n closed pmin pmax dev < <(pressureStats "$c" 1 punchBlock)
    echo "    force control: top at $(summaryValue "$c" topZ), interface pressure $pmin .. $pmax (exact $p)"
    checkClose "force control: the punch's top at 7 - 0.01" "$(summaryValue "$c" topZ)" 6.99 1e-7
    checkClose "force control: bottom reaction = F" "$(summaryValue "$c" bottomReaction)" "$F" 1e-8
    checkBelow "force control: interface pressure, max relative error" "$dev" 1e-6
    newtonChecks "force control" "$c"
else
    fail "force-controlled run (see $c/log.formFoam)"
fi

[ -n "${KEEP:-}" ] && echo "    kept $work" || rm -rf "$work"
