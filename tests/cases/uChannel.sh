#!/usr/bin/env bash
# NUMISHEET'93 U-channel (tutorials/numisheet93UChannel) at reduced size and
# the hard contact cases of the forming process.
# 1. Regression: the tutorial as it is (105 x 1 elements, forming +
#    springback) reproduces the values of the run recorded in
#    uChannel.reference (provenance in that file) within 0.05 deg (theta1,
#    theta2) and 1 % (rho, punchForceMax). There is no independent
#    reference for these numbers (the NUMISHEET'93 experiments could not be
#    consulted; README of the tutorial): this test guards against changes
#    of the result, the mesh and eps studies of the README against its
#    accuracy. Springback must cost less than forming (the paper: below
#    0.1 of it). Newton converges quadratically at the end of the steps
#    (observed order, median over the steps, at least 1.8).
# 2. Hard cases, forming to a 5 mm stroke only (what they test is decided
#    at first contact, in the first millimetres):
#    a. punch and die radii equal to 2 t (1.56 mm) instead of 5 mm;
#    b. the blank holder starts 2 mm above the blank: force-controlled, it
#       is moved onto the blank before the first step (no singular
#       system), and ends on the blank (holderPosition ~ -2 mm);
#    Both must run to the end without failure.
# 3. The tutorial as a dynamic problem at the real tool speed against the
#    static run of 1 (below).
# 4. The U-channel from MITC4 shells (tutorials/numisheet93UChannel/shells,
#    reduced as its README's "Test" section says: 10 + 120 + 10 elements,
#    0.83 mm where the blank bends, 5 Gauss points) against the 2D
#    reference run (uChannel.reference) within the bounds the README
#    derives from the 2D case's own mesh error, the step scatter and the
#    kinematics the shells lack: theta1 3.9 deg, theta2 2.6 deg, the wall
#    curvature 1/rho 2.6e-3 per mm (observed +0.93 deg, -0.82 deg,
#    2.2e-3 per mm on the README's run; 0.91 deg, 0.97 deg, 2.3e-3 per mm
#    since 2026-11-27: the 2D reference's new step sequence and the
#    shells' contact compliance).
# 5. A straight hat section of the benchmark's 35 mm strip from shells
#    (the shells case with -width 17.5 -across 2 -freeEdge: half the width
#    with 2 elements across, the face z = 17.5 free, the same reduced mesh
#    along the blank): its middle section (z = 0, a symmetry plane)
#    against the plane-strain strip of 4, the same build and mesh. Under
#    load the middle of a 35 mm strip bent over R/t = 6.4 is in plane
#    strain (the free edge's layer is about sqrt(R t) = 2 mm wide; the
#    shells README's study: within 0.03 deg, 0.011 with 6 elements
#    across). Two elements across, not 3 (until 2026-11-29): 3 took 974 s
#    of the suite's 30 minutes, 2 take about half; their discretisation
#    error is in the bounds. The two runs take different step sequences,
#    and every number below scatters with the step sequence: the strip
#    alone, rerun with the first deltaT 0.009, 0.01 and 0.011 and with
#    the contact predictor of 2026-11-28, gave theta1Formed 90.48-90.67,
#    released theta1 91.49-92.23 and the thinnest element 0.7638-0.7728
#    mm (shells README, "A straight hat section"). Bounds: the formed
#    angles within 0.25 deg (that scatter, 0.18, plus the width's 0.04
#    with 2 across against 6); the released angles within 1.5 deg (the
#    step scatter, 0.74 deg, plus the width's discretisation: 2 against 6
#    elements across moved theta2 by 0.74 deg and theta1 by 0.43); the
#    wall curvature 1/rho within 1.2e-3 per mm (the step scatter of this
#    nearly straight wall, 5.6e-4 per mm per halving of the step (../../
#    tutorials/numisheet93UChannel/README.md), plus the free edge's own
#    effect, 3.8e-4 per mm with 6 elements across, plus 2 against 6
#    across, 2.1e-4); the thinnest element within 2 % (its step scatter
#    1.2 %). Observed on 2026-11-29 (formFoam 9bac3f8): 0.13 and 0.007
#    deg formed, 0.27 and 0.32 deg released, 1.8e-4 per mm, 0.02 %.
#    README of the shells case: "A straight hat section".
# Chattering detection is tested at kernel level (formKernelTests,
# contactModel.chatteringIsReported) and shows in the U-channel logs as
# cut-back steps naming the node.
. "$(dirname "$0")/testFunctions"
here=$(cd "$(dirname "$0")" && pwd)

# value <case> <entry>: full precision from postProcessing/summary
value() { summaryValue "$1" "$2"; }
# ref <entry>: recorded reference value
ref() { awk -v e="$1" '$1 == e { print $2 }' "$here/uChannel.reference"; }
# stroke <case> <mm>: forming to the given punch travel only (time scaled)
stroke()
{
    local c=$1 s=$2
    local t
    t=$(awk -v s="$s" 'BEGIN { printf "%.6g", s/70.1 }')
    sed -i "s/^endTime .*/endTime         $t;/" "$c/system/controlDict"
    python3 - "$c/constant/processSchedule" "$t" <<'EOF' || fail "U-channel stroke: cannot edit processSchedule"
import sys
p, t = sys.argv[1], sys.argv[2]
s = open(p).read()
s = s[:s.index('steps')] + 'steps { forming { endTime %s; deltaT 0.002; maxDeltaT 0.01; } }\n' % t
open(p, 'w').write(s)
EOF
    # springback entries need a formed channel: keep the forming ones only
    # (every one of them must be found: a renamed entry fails the edit)
    python3 - "$c/system/solidSolution" <<'EOF' || fail "U-channel stroke: an entry to remove from solidSolution is missing"
import sys, re
p = sys.argv[1]
s = open(p).read()
for name in ('theta1', 'theta2', 'rho', 'theta1Formed', 'theta2Formed', 'punchForce'):
    s, n = re.subn(r'\n    %s\s*\{[^}]*\}' % name, '', s)
    if n != 1:
        sys.exit(1)
open(p, 'w').write(s)
EOF
}

# reducedShells <case>: the test's reduction of the shells case (its
# README, "Test"): 10 + 120 + 10 elements along the blank, 0.83 mm where
# it bends, 5 Gauss points through the thickness
reducedShells()
{
python3 - "$1/system/blank/blockMeshDict" <<'EOF' || fail "U-channel shells: cannot edit blockMeshDict"
import sys
p = sys.argv[1]
s = open(p).read()
# three blocks along the blank: x < 25 (10 elements), 25..125 (120: the
# tutorial's 0.83 mm), > 125 (10)
a = s.index('vertices')
s = s[:a] + '''vertices
(
    (0 0 0) (25 0 0) (125 0 0) ($L 0 0)
    (0 $t 0) (25 $t 0) (125 $t 0) ($L $t 0)
    (0 0 $W) (25 0 $W) (125 0 $W) ($L 0 $W)
    (0 $t $W) (25 $t $W) (125 $t $W) ($L $t $W)
);
blocks
(
    hex (0 1 5 4 8 9 13 12) (10 1 1) simpleGrading (1 1 1)
    hex (1 2 6 5 9 10 14 13) (120 1 1) simpleGrading (1 1 1)
    hex (2 3 7 6 10 11 15 14) (10 1 1) simpleGrading (1 1 1)
);
boundary
(
    left   { type patch; faces ((0 8 12 4)); }
    right  { type patch; faces ((3 7 15 11)); }
    bottom { type patch; faces ((0 1 9 8) (1 2 10 9) (2 3 11 10)); }
    top    { type patch; faces ((4 12 13 5) (5 13 14 6) (6 14 15 7)); }
    front  { type patch; faces ((0 4 5 1) (1 5 6 2) (2 6 7 3)); }
    back   { type patch; faces ((8 9 13 12) (9 10 14 13) (10 11 15 14)); }
);

'''
open(p, 'w').write(s)
EOF
sed -i 's/^\( *thicknessPoints\) 7;/\1 5;/' "$1/constant/blank/solidProperties"
grep -q "thicknessPoints 5;" "$1/constant/blank/solidProperties" \
    || fail "U-channel shells: cannot set 5 thickness points"
}

#------------------------------------------------------------------------------
# 1. The tutorial against the recorded run
c=$(caseCopy numisheet93UChannel)
if (cd "$c" && timeout 1800 ./Allrun > log.Allrun 2>&1); then
    for q in theta1 theta2; do
        v=$(value "$c" $q); r=$(ref $q)
        if awk -v v="$v" -v r="$r" 'BEGIN { d = v - r; if (d < 0) d = -d; exit !(v != "" && d <= 0.05) }'
        then pass "U-channel: $q $v vs recorded run $r (0.05 deg; regression, own code)"
        else fail "U-channel: $q $v vs recorded run $r (0.05 deg; regression, own code)"; fi
    done
    checkClose "U-channel: rho vs recorded run (regression)" "$(value "$c" rho)" "$(ref rho)" 0.01
    checkClose "U-channel: punchForceMax vs recorded run (regression)" \
        "$(value "$c" punchForceMax)" "$(ref punchForceMax)" 0.01
    checkBelow "U-channel: springback / forming wall time" \
        "$(awk -v s="$(value "$c" springbackWallTime)" -v f="$(value "$c" formingWallTime)" \
            'BEGIN { printf "%.4g", s/f }')" 0.5
    # Newton's order in the last iterations of the steps (energy norms;
    # median over the steps): quadratic once the contact status is found
    q=$(newtonOrder "$c/log.formFoam")
    checkBelow "U-channel: Newton order (median over the steps) above 1.8" 1.8 "$q"
else
    fail "U-channel run (see $c/log.formFoam)"
    tail -15 "$c/log.formFoam" | sed 's/^/    | /'
fi
static=$c

#------------------------------------------------------------------------------
# 3. The same run as a dynamic problem at the real tool speed (Allrun
#    -dynamic: Bathe scheme, steel density, 70 mm/s, no mass scaling;
#    springback static) gives the static angles: within 0.7 deg (recorded
#    differences -0.30 deg for theta1, +0.18 for theta2, the effect of the
#    different steps: the static angles move by 0.15-0.25 deg per halving
#    of the step) and the punch force within 5 % (-0.4 %); the inertia is
#    negligible (the
#    largest kinetic energy below 1e-5 of the work done on the blank)
d=$(caseCopy numisheet93UChannel)
if (cd "$here/../../tutorials/numisheet93UChannel" && timeout 1800 ./Allrun -case "$d" -dynamic > "$d/log.Allrun" 2>&1) \
    && [ -f "$d/postProcessing/energy.dat" ]
then
    for q in theta1 theta2; do
        v=$(value "$d" $q); r=$(value "$static" $q)
        if awk -v v="$v" -v r="$r" 'BEGIN { d = v - r; if (d < 0) d = -d; exit !(v != "" && r != "" && d <= 0.7) }'
        then pass "U-channel dynamic (70 mm/s): $q $v vs static $r (0.7 deg)"
        else fail "U-channel dynamic (70 mm/s): $q $v vs static $r (0.7 deg)"; fi
    done
    checkClose "U-channel dynamic: punchForceMax vs static" \
        "$(value "$d" punchForceMax)" "$(value "$static" punchForceMax)" 0.05
    checkBelow "U-channel dynamic: largest kinetic energy / work on the blank" \
        "$(awk '!/^#/ { if ($2 > k) k = $2; w = $4 } END { printf "%.3g", k/w }' "$d/postProcessing/energy.dat")" 1e-5
    # The effect report says so too (largest kinetic energy / largest
    # internal work), and that the plastic flow matters
    checkEffect "U-channel dynamic: effect report" "$d" inertia kineticToInternal negligible
    checkEffect "U-channel dynamic: effect report" "$d" plasticity plasticDissipation matters
else
    fail "U-channel dynamic run (see $d/log.formFoam)"
    tail -15 "$d/log.formFoam" | sed 's/^/    | /'
fi
[ -n "${KEEP:-}" ] || rm -rf "$static" "$d"

#------------------------------------------------------------------------------
# 4. The shells against the 2D reference
c=$(caseCopy numisheet93UChannel/shells)
reducedShells "$c"
if (cd "$c" && timeout 1800 ./Allrun > log.Allrun 2>&1); then
    pass "U-channel shells: 140 MITC4 x 5 points, $(value "$c" steps) steps," \
        "$(value "$c" newtonIterationsPerStep) Newton its/step," \
        "$(value "$c" wallTime) s"
    checkBelow "U-channel shells: |theta1 - 2D reference| (deg)" \
        "$(calc 'abs(v - r)' v="$(value "$c" theta1)" r="$(ref theta1)")" 3.9
    checkBelow "U-channel shells: |theta2 - 2D reference| (deg)" \
        "$(calc 'abs(v - r)' v="$(value "$c" theta2)" r="$(ref theta2)")" 2.6
    checkBelow "U-channel shells: |1/rho - 1/rho of the 2D reference| (1/mm)" \
        "$(calc 'abs(1/v - 1/r)' v="$(value "$c" rho)" r="$(ref rho)")" 2.6e-3
else
    fail "U-channel shells run (see $c/log.formFoam)"
    tail -15 "$c/log.formFoam" | sed 's/^/    | /'
fi
strip=$c

#------------------------------------------------------------------------------
# 5. A straight hat section from shells against the strip of 4
h=$(caseCopy numisheet93UChannel/shells)
reducedShells "$h"
if timeout 2400 "$here/../../tutorials/numisheet93UChannel/shells/Allrun" -case "$h" \
       -width 17.5 -across 2 -freeEdge > "$h/log.Allrun" 2>&1 \
    && [ -f "$strip/postProcessing/summary" ]
then
    pass "U-channel hat section: 140 x 2 MITC4 over 17.5 mm, free edge," \
        "$(value "$h" steps) steps, $(value "$h" newtonIterationsPerStep) Newton its/step," \
        "$(value "$h" wallTime) s"
    for q in theta1Formed theta2Formed; do
        checkBelow "U-channel hat section: |$q - the strip's| (deg, under load)" \
            "$(calc 'abs(v - r)' v="$(value "$h" $q)" r="$(value "$strip" $q)")" 0.25
    done
    for q in theta1 theta2; do
        checkBelow "U-channel hat section: |$q - the strip's| (deg, released)" \
            "$(calc 'abs(v - r)' v="$(value "$h" $q)" r="$(value "$strip" $q)")" 1.5
    done
    checkBelow "U-channel hat section: |1/rho - the strip's| (1/mm)" \
        "$(calc 'abs(1/v - 1/r)' v="$(value "$h" rho)" r="$(value "$strip" rho)")" 1.2e-3
    checkClose "U-channel hat section: thicknessMin vs the strip's" \
        "$(value "$h" thicknessMin)" "$(value "$strip" thicknessMin)" 0.02
else
    fail "U-channel hat section run (see $h/log.formFoam)"
    tail -15 "$h/log.formFoam" | sed 's/^/    | /'
fi
[ -n "${KEEP:-}" ] || rm -rf "$strip" "$h"

#------------------------------------------------------------------------------
# hardCase <label> <sed expression>: a 5 mm stroke of the tutorial with
# contactProperties edited (an edit that changes nothing fails: sed in
# testFunctions); must run through. Leaves the case in $c for further
# checks.
hardCase()
{
    c=$(caseCopy numisheet93UChannel)
    stroke "$c" 5
    sed -i "$2" "$c/constant/contactProperties"
    if (cd "$c" && blockMesh -region blank > log.blockMesh 2>&1 && formFoam > log.formFoam 2>&1)
    then
        pass "U-channel $1: 5 mm stroke, $(value "$c" steps) steps, $(value "$c" cutbacks) cutbacks"
        return 0
    fi
    fail "U-channel $1 (see $c/log.formFoam)"
    tail -15 "$c/log.formFoam" | sed 's/^/    | /'
    return 1
}

# 2a. Tool radii of 2 t (punch and die)
hardCase "with punch and die radii 2 t = 1.56 mm" \
    's/radii       (5);/radii       (1.56);/'
[ -n "${KEEP:-}" ] || rm -rf "$c"

# 2b. Blank holder force applied before contact exists
if hardCase "with the holder 2 mm above the blank" \
    's/(40.78 0.78) (200 0.78)/(40.78 2.78) (200 2.78)/'
then
    checkClose "U-channel lifted holder: final holder translation vs -2 mm" \
        "$(value "$c" holderPosition)" -2 0.05
fi
[ -n "${KEEP:-}" ] || rm -rf "$c"
