#!/usr/bin/env bash
# Contact with rigid tools (constraint-function method, constant/
# contactProperties), linear elastic bodies (E = 200000, nu = 0.3; the
# linearElastic material is geometrically linear, linearElastic.H), plane
# strain, forces per unit depth. Contact results are read from
# postProcessing/contact/<time>/<pair>.dat (consistent nodal forces;
# pressure = normalForce / weight, the weight int N_a ds taken on the
# CURRENT surface).
#
# 1. Flat frictionless punch wider than the block (tests/cases/flatPunch:
#    block 10 x 5, x fixed on the left (symmetry), rollers at the bottom,
#    punch displaced down by 0.01; x-graded mesh, so the contactor nodes
#    carry unequal consistent weights). Exact solution of the FE problem:
#    the homogeneous plane-strain uniaxial-stress state sigma_xx = 0,
#    eps_zz = 0 (Hooke's law, e.g. Timoshenko & Goodier, Theory of
#    Elasticity, 3rd ed. 1970, sec. 16):
#        sigma_yy = E/(1 - nu^2) eps_yy,   eps_yy = -0.01/5,
#        eps_xx = -nu/(1 - nu) eps_yy      (free lateral expansion)
#    With linear kinematics sigma_yy is per reference area, so the total
#    force is exactly F = E/(1 - nu^2) 0.01/5 x 10 (= toolForce = sum of
#    the nodal normal forces = bottom reaction), while the pressure
#    (force / current width) is uniform and equals
#        p = E/(1 - nu^2) (0.01/5) / (1 + nu/(1 - nu) 0.01/5)
#    (every node equal to the mean within 1e-6, the mean within 1e-6).
#    The case sets epsilonN = 1e-16: the regularised normal law leaves each
#    closed node at a gap g = epsilonN/lambda (lambda = f/E, f the nodal
#    force), which differs between corner and mid-side nodes (consistent
#    forces 1:4:1); with the automatic law (g f = epsN k = 1e-10 E l^2,
#    contactModel.H) these gaps are up to 1.6e-7 and the pressures differ
#    by up to 1.2e-4 of the mean; with epsN = 1e-16 (and the automatic
#    k = 1e-4 E) the gaps are ~1e-17.
# 2. Hertz line contact (tests/cases/hertz): rigid cylinder R = 50 (an
#    exact circular fillet of a V outline) on a 25 x 25 half model (> 20 a)
#    (symmetry x = 0, bottom fixed; 0.1-wide elements under the contact),
#    motion-controlled indentation 0.04. From the total force per unit
#    depth P (2 x the half model's toolForce), Hertz plane strain
#    (Johnson, Contact Mechanics, 1985, sec. 4.3, eqs. 4.43-4.45 with the
#    second body rigid):
#        E* = E/(1 - nu^2),  a = sqrt(4 P R/(pi E*)),  p0 = 2 P/(pi a)
#    FE: p0 = the largest nodal pressure, a = the contact edge, located by
#    the semi-ellipse p^2 = p0^2 (1 - x^2/a^2) through the last two nodes
#    in contact, i.e. carrying more than 1 % of the peak pressure (p^2
#    linear in x^2; the edge so found lies between the last contact node
#    and the next one; the closed flag lambda > g would also count nodes
#    just outside whose gap is below sqrt(epsN), with negligible force).
#    Within 1.5 % (p0) and 2 % (a): observed +0.44 % and -0.60 %; an E*
#    off by 10 % moves both by 5 %. The same with
#    the cylinder force-controlled (starting 0.01 above the block, pushed
#    down with the motion run's force): the same peak pressure (1e-6), the
#    same contact half-width (1e-3) and a final translation of -(0.04 + 0.01)
#    (1e-5; the two runs reach the same state).
# 3. Block 2 x 1 on a fixed rigid flat ground, Coulomb friction mu = 0.3,
#    dead traction 100 on the top: N = 200 (tests/cases/slidingBlock).
#    Coulomb's law (e.g. Johnson 1985, sec. 7.1; Wriggers, Computational
#    Contact Mechanics, 2nd ed. 2006, sec. 5.2): |F_t| <= mu N, and
#    F_t = mu N = 60 when the whole contact slides. The default law
#    (alartCurnier, constraintFunctions.H) carries mu lambda in sliding to
#    O(epsT/(r s)) and lets a sticking node creep at O(r epsT/(mu lambda));
#    the case sets sqrt(epsT) = 1e-6 per unit time, 1/1000 of the slowest
#    push (2.5e-5 per step of 0.025). (d) repeats (a) and (b) with the
#    regularised law tau = -mu lambda s/sqrt(s^2 + epsT) (s: sliding
#    velocity, slip over a step / deltaT), which carries mu lambda (1 -
#    O(epsT/s^2)) and lets a sticking node creep at up to a few sqrt(epsT).
#    (a) the left face pushed far (0.01) in x: friction force = mu N
#        within 0.5 % (toolForce; also = the sum of the nodal tangential
#        forces, 1e-8). In the last steps (steady
#        sliding; push (0.01 - 0.001)/4 = 0.00225 per step) every bottom
#        node slips by the push increment: the
#        slip column (xi - xi_n over the step) must show it (1e-3).
#    (b) pressed with the left face held, then the left face released and
#        pulled by a traction T = 40 < mu N (T x height 1): sticking, the
#        ground's friction force equals the applied force T (equilibrium,
#        1e-6) and the bottom nodes hardly move during the pull: the
#        regularised law lets a sticking node creep by sqrt(epsT) r/sqrt(1
#        - r^2) per step (r = |shear|/(mu pressure) < 1; r <= 0.94 here),
#        so the bound is 10 sqrt(epsT) per step over the 4 pull steps,
#        i.e. 2e-5 of the block length (sliding would be macroscopic: the
#        block has no other support in x). Observed 1.2e-6 of the length
#        with the Alart-Curnier law (bound 5e-6) and 2.4e-6 with the
#        regularised law.
#    (c) the push of (a) in steps of 2.5e-5 through the transition: in the
#        first step where the bottom-right node (whose x displacement is
#        its slip: the ground is fixed) slips by more than half the push
#        increment, i.e. moves with the pusher, the friction force is mu N
#        within 2 %.
# 5. Elastic punch 10 x 2 on the elastic block 10 x 5 (tests/cases/
#    flatPunchDeformable: two bodies of one region, the punch's bottom
#    nodes against the block's top edges; punch top pushed down by 0.01,
#    both left faces symmetric, block bottom on rollers, same material).
#    Exact: both bodies in the homogeneous state of test 1 with
#    eps_yy = -0.01/7, so the same lateral expansion, a frictionless
#    interface and the uniform pressure
#        p = E/(1 - nu^2) (0.01/7) / (1 + nu/(1 - nu) 0.01/7)
#    and the force F = E/(1 - nu^2) 0.01/7 x 10 on both ends.
#    (a) matching meshes (8 + 8 elements along x) and (b) a punch of 16
#        (its nodes include all the block's): node-to-segment transmits
#        the uniform pressure exactly (1e-6) and F (1e-8).
#    (c) non-matching meshes (punch 5, 7, 11, 13 elements): single-pass
#        node-to-segment does not pass the contact patch test (Taylor &
#        Papadopoulos 1991; Wriggers, Computational Contact Mechanics,
#        2006, sec. 9.3). The test prints the error pattern (nodal pressure
#        range, force error) and checks: global equilibrium (punch
#        reaction = bottom reaction, 1e-8), Newton in at most 6 iterations
#        per step (a contactor node over a target corner node must not make
#        Newton cycle between the two edges: deformableTarget.H,
#        Hysteresis), and the recorded error levels as bounds (pressure
#        within 35 % of p with a coarser punch (5, 7), 15 % with a finer
#        one (11, 13); force within 2.5 % and 0.1 %).
#    (d) two-pass (a second pair with the roles swapped), punch 5 and 7:
#        force within 0.2 % (single pass: 2.5 %), equilibrium, Newton
#        cost unchanged.
# 6. Restart inside a tool-release ramp (flat punch, see below).
. "$(dirname "$0")/testFunctions"
here=$(cd "$(dirname "$0")" && pwd)
pi=$(awk 'BEGIN { printf "%.15g", atan2(0, -1) }')

# newCase <case dir under tests/cases>: a scratch copy -> prints its path
newCase()
{
    local d
    d=$(mktemp -d "${TMPDIR:-/tmp}/formFoamContact.XXXXXX")
    cp -r "$here/$1/." "$d/"
    echo "$d"
}
# run <case>: mesh + solve; non-zero exit on failure
run() { (cd "$1" && blockMesh -region block > log.blockMesh 2>&1 && formFoam > log.formFoam 2>&1); }
# summary <case> <entry>: full precision (foamDictionary -value prints 6 digits)
summary() { summaryValue "$1" "$2"; }
# contactFile <case> <time> <pair>
contactFile() { echo "$1/postProcessing/contact/$2/$3.dat"; }
keepOrRemove() { [ -n "${KEEP:-}" ] && echo "    kept $*" || rm -rf "$@"; }
reportFailure() { fail "$1 (see $2/log.formFoam)"; tail -15 "$2/log.formFoam" | sed 's/^/    | /'; }
# restartCopy <case> <time> <later time dirs...>: a copy of the run <case>
# without the later times (postProcessing kept, as a user would), restarted at <time>; prints
# its path. restarted <copy> <time>: formFoam ran and read that state
restartCopy()
{
    local c=$1 t=$2 r
    shift 2
    r=$(mktemp -d "${TMPDIR:-/tmp}/formFoamContact.XXXXXX")
    cp -r "$c/." "$r/"
    for d in "$@"; do rm -rf "${r:?}/$d"; done
    sed -i "s/^startTime .*/startTime       $t;/" "$r/system/controlDict"
    echo "$r"
}
restarted()
{
    (cd "$1" && formFoam > log.restart 2>&1) \
        && grep -q "Restarting from the state written at time $2" "$1/log.restart"
}
# slidingRestart <label> <case> <time> <later time dirs...>: restart the
# sliding-block run <case> at <time>; friction force and slip of the
# bottom-right node must equal the continuous run's (1e-8)
slidingRestart()
{
    local label=$1 c=$2 t=$3 r
    shift 3
    r=$(restartCopy "$c" "$t" "$@")
    if restarted "$r" "$t"; then
        pass "$label: reads the state at t = $t"
        checkClose "$label: friction force vs continuous run" \
            "$(summary "$r" frictionForce)" "$(summary "$c" frictionForce)" 1e-8
        checkClose "$label: slip of the bottom-right node vs continuous run" \
            "$(summary "$r" slipRight)" "$(summary "$c" slipRight)" 1e-8
    else
        fail "$label (see $r/log.restart)"
        tail -15 "$r/log.restart" | sed 's/^/    | /'
    fi
    keepOrRemove "$r"
}

#------------------------------------------------------------------------------
# 1. Flat punch
c=$(newCase flatPunch)
if run "$c"; then
    f=$(contactFile "$c" 1 blockTop)
    sRef=$(awk 'BEGIN { printf "%.12g", 200000/(1 - 0.3^2)*0.01/5 }')
    pRef=$(awk -v s="$sRef" 'BEGIN { printf "%.12g", s/(1 + 0.3/(1 - 0.3)*0.01/5) }')
    # columns: node X Y x y gap normalForce tangentialForce weight pressure shear slip closed
    read -r n nClosed pMean dev sumFn < <(awk '!/^#/ && NF >= 13 {
        ++n; p[n] = $10; s += $10; fn += $7; if ($13 == 1) ++c }
        END { if (!n) exit; m = s/n; d = 0
              for (i = 1; i <= n; ++i) { e = (p[i] - m)/m; if (e < 0) e = -e; if (e > d) d = e }
              printf "%d %d %.12g %.3g %.12g\n", n, c, m, d, fn }' "$f")
    echo "    flat punch: $n contactor nodes, $nClosed closed, mean pressure $pMean, max |p - mean|/mean $dev"
    [ "$nClosed" = "$n" ] && [ "$n" -gt 0 ] && pass "flat punch: all $n top nodes closed" \
        || fail "flat punch: $nClosed of $n top nodes closed"
    checkBelow "flat punch: uniform pressure, max |p - mean|/mean" "$dev" 1e-6
    checkClose "flat punch: mean pressure vs E/(1 - nu^2) 0.01/5 per current width" "$pMean" "$pRef" 1e-6
    F=$(summary "$c" punchForce)
    checkClose "flat punch: toolForce vs E/(1 - nu^2) 0.01/5 x 10" "$F" \
        "$(awk -v s="$sRef" 'BEGIN { printf "%.12g", 10*s }')" 1e-8
    checkClose "flat punch: sum of nodal normal forces vs toolForce" "$sumFn" "$F" 1e-8
    checkClose "flat punch: bottom reaction vs toolForce" "$(summary "$c" bottomReaction)" "$F" 1e-8
else
    reportFailure "flat punch run" "$c"
fi
keepOrRemove "$c"

#------------------------------------------------------------------------------
# 2. Hertz line contact
# hertzResult <case> <time>: prints "pmax aFE nClosed"
hertzResult()
{
    awk '!/^#/ && NF >= 13 { x[NR] = $4; p[NR] = $10; cl[NR] = $13; k[++n] = NR }
    END {
        if (!n) exit    # no data: nothing (the checks fail)
        # sort the nodes by current x (insertion sort: ~70 nodes)
        for (i = 2; i <= n; ++i) { j = i; while (j > 1 && x[k[j-1]] > x[k[j]]) { t = k[j]; k[j] = k[j-1]; k[j-1] = t; --j } }
        # contact set: the nodes carrying more than 1 % of the peak
        # pressure (the closed flag, lambda > g, also takes nodes whose
        # gap is below sqrt(epsN) with negligible force)
        pmax = 0; last = 0; nc = 0
        for (i = 1; i <= n; ++i) if (p[k[i]] > pmax) pmax = p[k[i]]
        for (i = 1; i <= n; ++i) if (p[k[i]] > 0.01*pmax) { ++nc; last = i }
        if (last < 2 || last == n) { print pmax, "nan", nc; exit }
        x1 = x[k[last-1]]; p1 = p[k[last-1]]; x2 = x[k[last]]; p2 = p[k[last]]
        # semi-ellipse through the last two contact nodes: p^2 linear in x^2
        a2 = x2*x2 + p2*p2*(x2*x2 - x1*x1)/(p1*p1 - p2*p2)
        printf "%.10g %.10g %d %.6g %.6g\n", pmax, sqrt(a2), nc, x2, x[k[last+1]]
    }' "$(contactFile "$1" "$2" blockTop)"
}
# hertzRef <P full>: prints "a p0"
hertzRef()
{
    awk -v P="$1" -v pi="$pi" 'BEGIN { if (P == "" || P != P + 0) exit; Es = 200000/(1 - 0.3^2); R = 50
        a = sqrt(4*P*R/(pi*Es)); printf "%.10g %.10g\n", a, 2*P/(pi*a) }'
}
# hertzChecks <label> <case>: checks; sets hP (full force) and hA (FE a)
hertzChecks()
{
    local a p0 pmax nc xc xo
    hP=$(calc '2*h' h="$(summary "$2" halfForce)")
    read -r a p0 < <(hertzRef "$hP")
    read -r pmax hA nc xc xo < <(hertzResult "$2" 1)
    echo "    Hertz ($1): P = $hP, a = $a, p0 = $p0; FE: p_max = $pmax, a = $hA" \
         "($nc contact nodes, last x = $xc, next x = $xo)"
    # observed: p_max +0.44 %, a -0.60 %; E* off by 10 % moves both by 5 %
    checkClose "Hertz ($1): max pressure vs p0 = 2P/(pi a)" "$pmax" "$p0" 0.015
    checkClose "Hertz ($1): contact half-width vs a = sqrt(4PR/(pi E*))" "$hA" "$a" 0.02
    hPmax=$pmax
}
c=$(newCase hertz)
indentation=0.04      # as in tests/cases/hertz/constant/contactProperties
if run "$c"; then
    hertzChecks "motion-controlled" "$c"
    am=$hA; pm=$hPmax
    # force-controlled: the cylinder starts 0.01 above the block and is
    # pushed down with the (half model's) force of the motion-controlled run
    cf=$(newCase hertz)
    Fh=$(summary "$c" halfForce)
    cat > "$cf/constant/contactProperties" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; location "constant"; object contactProperties; }
tools
{
    cylinder
    {
        // as the motion-controlled case, 0.01 higher
        profile     ((-60 39.299321881345245) (0 -20.700678118654755) (60 39.299321881345245));
        radii       (50);
        force       table ((0 0) (1 $Fh));
        direction   (0 -1 0);
    }
}
pairs
{
    blockTop { patch top; tool cylinder; friction 0; }
}
DICT
    if run "$cf"; then
        hertzChecks "force-controlled" "$cf"
        # (the tool's force itself is the force it was given, to the
        # Newton tolerance: no check; the state it reaches is)
        checkClose "Hertz: force-controlled max pressure vs motion-controlled" "$hPmax" "$pm" 1e-6
        checkClose "Hertz: force-controlled contact half-width vs motion-controlled" "$hA" "$am" 1e-3
        checkClose "Hertz: force-controlled translation vs -(indentation + gap 0.01)" \
            "$(summary "$cf" toolY)" "$(awk -v d="$indentation" 'BEGIN { printf "%.10g", -(d + 0.01) }')" 1e-5
    else
        reportFailure "Hertz run (force-controlled)" "$cf"
    fi
    keepOrRemove "$cf"
else
    reportFailure "Hertz run (motion-controlled)" "$c"
fi
keepOrRemove "$c"

#------------------------------------------------------------------------------
# 4. Bad contact input stops with a message naming the file and the entry
#    (flat punch case)
bad=$(newCase flatPunch)
(cd "$bad" && blockMesh -region block > log.blockMesh 2>&1) || fail "blockMesh (bad input)"
cp=constant/contactProperties
# tryContact <label> <regex> <command to break the copy...>
tryContact()
{
    local label=$1 regex=$2; shift 2
    local d
    d=$(newCase flatPunch)
    cp -r "$bad/." "$d/"
    (cd "$d" && eval "$@")
    (cd "$d" && timeout 120 formFoam > log.formFoam 2>&1)
    expectFailure "contact input: $label" $? "$d/log.formFoam" "$regex"
    rm -rf "$d"
}
tryContact "mistyped pair entry" "Unknown entry 'frction'.*blockTop" \
    "sed -i 's/friction 0;/frction 0;/' $cp"
tryContact "unknown tool" "Unknown tool 'punsh'.*contactProperties" \
    "sed -i 's/tool punch;/tool punsh;/' $cp"
tryContact "unknown patch" "Unknown patch 'topp'.*contactProperties" \
    "sed -i 's/patch top;/patch topp;/' $cp"
tryContact "negative friction" "'friction'.*must be >= 0" \
    "sed -i 's/friction 0;/friction -0.1;/' $cp"
tryContact "negative fillet radius" "Entry 'radii'.*contactProperties" \
    "sed -i 's/^        motion /        radii (0 -1);\n        motion /' $cp"
tryContact "fillet that does not fit" "Entry 'radii'.*contactProperties" \
    "sed -i 's/^        motion /        radii (0 50);\n        motion /' $cp"
tryContact "force-controlled tool moving away from the body" "tool 'punch'.*never touch" \
    "sed -i 's|^        motion .*|        force constant 100; direction (0 1 0);|' $cp"
tryContact "motion and force on one tool" "both 'motion' and 'force'" \
    "sed -i 's|^        motion \(.*\)|        motion \1 force constant 1; direction (0 -1 0);|' $cp"
tryContact "pair with both a tool and a target patch" "needs either 'tool'.*'targetPatch'" \
    "sed -i 's/tool punch;/tool punch; targetPatch bottom;/' $cp"
tryContact "unknown target patch" "Unknown patch 'topp'.*entry 'targetPatch'" \
    "sed -i 's/tool punch;/targetPatch topp;/' $cp"
tryContact "SPD solver with contact" "cholmod.*contact" \
    "sed -i 's/^linearSolver .*/linearSolver cholmod;/' system/solidSolution"
rm -rf "$bad"

#------------------------------------------------------------------------------
# 3. Sliding block: (a) + (c) in one run (press; push 0.001 in 40 steps;
#    push on to 0.01 in 4 steps)
muN=60
c=$(newCase slidingBlock)
if run "$c"; then
    Ft=$(summary "$c" frictionForce)
    echo "    sliding: N = $(summary "$c" normalForce), friction force $Ft, slip of the bottom-right node $(summary "$c" slipRight)"
    checkClose "sliding block: normal force vs applied 100 x 2" "$(summary "$c" normalForce)" 200 1e-8
    checkClose "(a) sliding: friction force (toolForce) vs mu N" "$Ft" "$muN" 0.005
    # the ground's outline runs in -x: tangentialForce > 0 points in -x
    sumFt=$(awk '!/^#/ && NF >= 13 { s += $8; ++n } END { if (n) printf "%.10g", s }' "$(contactFile "$c" 3 blockBottom)")
    checkClose "(a) sliding: sum of nodal tangential forces vs toolForce" "$sumFt" "$Ft" 1e-8
    read -r sMin sMax < <(awk '!/^#/ && NF >= 13 { s = $12 < 0 ? -$12 : $12; if (n++ == 0 || s < a) a = s; if (s > b) b = s }
        END { if (n) printf "%.6g %.6g\n", a, b }' "$(contactFile "$c" 3 blockBottom)")
    echo "    (a) |slip| over the last step (output column): min $sMin, max $sMax (push increment (0.01 - 0.001)/4 = 0.00225)"
    checkClose "(a) sliding: output slip over the last step (smallest node) vs push increment" "$sMin" 0.00225 1e-3
    # (c) history: # time frictionForce normalForce slipRight. Sliding
    # starts at the first step in which the bottom-right node slips by more
    # than half the push increment (2.5e-5 per step)
    read -r tc Fc dsc Fb < <(awk '!/^#/ {
        if ($1 > 1 && $1 <= 2 && $4 - prevS > 0.5*2.5e-5) { print $1, $2, $4 - prevS, prevF; found = 1; exit }
        prevS = $4; prevF = $2 }
        END { if (!found) print "none", "", "", "" }' "$c/postProcessing/history.dat")
    echo "    (c) first step sliding: t = $tc (push $(awk -v t="$tc" 'BEGIN { printf "%.4g", (t - 1)*0.001 }')), slip in the step $dsc, friction $Fc (previous step $Fb)"
    checkClose "(c) stick-slip transition: friction force in the first sliding step vs mu N" "$Fc" "$muN" 0.02
    # Restart from the state written at t = 2 (contact multipliers and
    # slip origins in 2/block/contactState): the sliding step continues
    # as in the uninterrupted run
    slidingRestart "restart inside a sliding step" "$c" 2 3
else
    reportFailure "sliding block run" "$c"
fi
keepOrRemove "$c"

# (b) sticking: press, then release the left face and pull it with T = 40;
# stickingBlock <law> <movement bound / length> <restart: yes|no>
stickingBlock()
{
local law=$1 bound=$2 restart=$3
c=$(newCase slidingBlock)
T=40
[ "$law" = alartCurnier ] || printf 'frictionLaw %s;\n' "$law" >> "$c/constant/contactProperties"
cat > "$c/constant/processSchedule" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; location "constant"; object processSchedule; }
steps
{
    press       { endTime 1; deltaT 0.5; }
    pull
    {
        endTime     2;
        deltaT      0.25;
        release     { left (x); }
        prescribe   { left { type traction; traction table ((1 (0 0 0)) (2 ($T 0 0))); } }
    }
}
DICT
sed -i 's/^endTime .*/endTime         2;/; s/^writeInterval .*/writeInterval   0.5;/' \
    "$c/system/controlDict"
if run "$c"; then
    Ft=$(summary "$c" frictionForce)
    checkClose "(b) sticking ($law): friction force vs applied T = $T" "$Ft" "$T" 1e-6
    # Restart at t = 1.5, inside the release ramp of the left face's
    # constraint (its reaction at t = 1 decays to zero over the pull): the
    # reaction at the restart state is the load still to ramp down
    [ "$restart" = yes ] && slidingRestart "(b) restart inside the constraint-release ramp" "$c" 1.5 2
    # slip during the pull: x movement of the bottom nodes between t = 1 and 2
    slip=$(awk '!/^#/ && NF >= 13 { if (FNR == NR) x[$1] = $4; else { ++n; d = $4 - x[$1]; if (d < 0) d = -d; if (d > m) m = d } }
        END { if (n) printf "%.3g", m }' "$(contactFile "$c" 1 blockBottom)" "$(contactFile "$c" 2 blockBottom)")
    maxSlipStep=$(awk '!/^#/ && NF >= 13 { d = $12 < 0 ? -$12 : $12; if (d > m) m = d } END { printf "%.3g", m }' \
        "$(contactFile "$c" 2 blockBottom)")
    echo "    (b) $law: max bottom-node movement during the pull $slip (block length 2), max |slip| column at t = 2: $maxSlipStep"
    checkBelow "(b) sticking ($law): max bottom-node movement / block length" \
        "$(calc 's/2' s="$slip")" "$bound"
else
    reportFailure "sticking block run ($law)" "$c"
fi
keepOrRemove "$c"
}
stickingBlock alartCurnier 5e-6 yes

# (d) the regularised law: sliding at mu N, and sticking within its creep
c=$(newCase slidingBlock)
printf 'frictionLaw regularised;\n' >> "$c/constant/contactProperties"
if run "$c"; then
    checkClose "(d) regularised law, sliding: friction force (toolForce) vs mu N" \
        "$(summary "$c" frictionForce)" "$muN" 0.005
else
    reportFailure "sliding block run (regularised law)" "$c"
fi
keepOrRemove "$c"
stickingBlock regularised 2e-5 no

#------------------------------------------------------------------------------
# 6. Restart inside a tool-release ramp (flat punch case): press (t 0 -> 1),
#    then releaseTools (punch) over t 1 -> 2 in four steps: the punch's
#    contact forces at t = 1 become loads that decay linearly to zero, so
#    the elastic block's top goes from -0.01 to -0.01 (2 - t): -0.0025 at
#    t = 1.75 and 0 at t = 2. A restart from t = 1.5 (inside the ramp:
#    the released flag and the ramped loads must be rebuilt from the
#    written state) must reproduce the continuous run (1e-8).
releaseCase()
{
    local d
    d=$(newCase flatPunch)
    cat > "$d/constant/processSchedule" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; location "constant"; object processSchedule; }
steps
{
    press   { endTime 1; deltaT 0.5; }
    release { endTime 2; deltaT 0.25; releaseTools (punch); }
}
DICT
    sed -i 's/^endTime .*/endTime         2;/; s/^writeInterval .*/writeInterval   0.25;/' \
        "$d/system/controlDict"
    sed -i 's|^    topDisplacement .*|    topDisplacement { type displacement; point (0 5 0); component y; }\
    topMidRelease { type displacement; point (0 5 0); component y; time 1.75; }\
    punchForceMax { type toolForce; tool punch; component y; scale -1; statistic max; }\
    topAtPress { type displacement; point (0 5 0); component y; time 0.75; }|' \
        "$d/system/solidSolution"
    echo "$d"
}
c=$(releaseCase)
if run "$c"; then
    uMid=$(summary "$c" topMidRelease)
    uEnd=$(summary "$c" topDisplacement)
    echo "    release ramp: top displacement $uMid at t = 1.75, $uEnd at t = 2"
    checkClose "release ramp: top displacement at t = 1.75 vs -0.01 x 0.25" "$uMid" -0.0025 1e-6
    checkBelow "release ramp: |top displacement| at t = 2 (fully released)" \
        "$(calc 'abs(u)' u="$uEnd")" 1e-9
    r=$(restartCopy "$c" 1.5 1.75 2)
    if restarted "$r" 1.5
    then
        pass "restart inside the release ramp reads the state at t = 1.5"
        checkClose "restart inside the release ramp: top displacement at t = 1.75 vs continuous run" \
            "$(summary "$r" topMidRelease)" "$uMid" 1e-8
        checkBelow "restart inside the release ramp: |top displacement| at t = 2" \
            "$(calc 'abs(u)' u="$(summary "$r" topDisplacement)")" 1e-9
        # the history before the restart is kept and replayed: the largest
        # punch force (at t = 1) and a value at t = 0.75 come out as in
        # the continuous run, and history.dat has each time once
        checkClose "restart: punchForceMax (reached before the restart) vs continuous run" \
            "$(summary "$r" punchForceMax)" "$(summary "$c" punchForceMax)" 1e-12
        checkClose "restart: value at t = 0.75 (before the restart) vs continuous run" \
            "$(summary "$r" topAtPress)" "$(summary "$c" topAtPress)" 1e-12
        if cmp -s <(awk '{ print $1 }' "$r/postProcessing/history.dat") \
                  <(awk '{ print $1 }' "$c/postProcessing/history.dat")
        then
            pass "restart: history.dat has the times of the continuous run"
        else
            fail "restart: history.dat times differ from the continuous run"
        fi
    else
        fail "restart inside the release ramp (see $r/log.restart)"
        tail -15 "$r/log.restart" | sed 's/^/    | /'
    fi
    keepOrRemove "$r"
else
    reportFailure "release ramp run" "$c"
fi
keepOrRemove "$c"

#------------------------------------------------------------------------------
# 5. Elastic punch on the elastic block (deformable target)
sD=$(awk 'BEGIN { printf "%.12g", 200000/(1 - 0.3^2)*0.01/7 }')
pD=$(awk -v s="$sD" 'BEGIN { printf "%.12g", s/(1 + 0.3/(1 - 0.3)*0.01/7) }')
FD=$(awk -v s="$sD" 'BEGIN { printf "%.12g", 10*s }')
# punchForceChecks <label> <punch force> <bottom force> <tolerance> <Newton
# iterations> <steps> [<bound>]: force against the exact one, equilibrium,
# Newton iterations per step at most <bound> (default 6)
punchForceChecks()
{
    checkClose "elastic punch ($1): punch reaction vs E/(1 - nu^2) 0.01/7 x 10" "$2" "$FD" "$4"
    checkClose "elastic punch ($1): punch reaction vs bottom reaction (equilibrium)" "$2" "$3" 1e-8
    checkBelow "elastic punch ($1): Newton iterations per step" \
        "$(calc 'i/s' i="$5" s="$6")" "${7:-6.01}"
}
# deformablePunch <nPunch> <pressure tolerance> <force tolerance> <label>
deformablePunch()
{
    local np=$1 ptol=$2 ftol=$3 label=$4 c f n nClosed pMin pMax dev its steps
    c=$(newCase flatPunchDeformable)
    # (the case as stored has nPunch 8: edit only another number)
    [ "$np" = 8 ] || sed -i "s/^nPunch .*/nPunch  $np;/" "$c/system/block/blockMeshDict"
    if run "$c"; then
        f=$(contactFile "$c" 1 punchBlock)
        read -r n nClosed pMin pMax dev < <(awk -v p="$pD" '!/^#/ && NF >= 13 {
            ++n; if ($13 == 1) ++c; e = ($10 - p)/p; if (e < 0) e = -e; if (e > d) d = e
            if (n == 1 || $10 < mn) mn = $10; if (n == 1 || $10 > mx) mx = $10 }
            END { if (n) printf "%d %d %.6g %.6g %.3g\n", n, c, mn, mx, d }' "$f")
        local F Fb
        F=$(summary "$c" punchReaction)
        Fb=$(summary "$c" bottomReaction)
        its=$(summary "$c" newtonIterations)
        steps=$(summary "$c" steps)
        echo "    elastic punch, $label ($np punch / 8 block elements): $nClosed of $n contactor nodes closed," \
             "nodal pressure $pMin .. $pMax (exact $pD, max error $dev), force $F (exact $FD)," \
             "Newton $its iterations in $steps steps"
        [ "$nClosed" = "$n" ] && [ "${n:-0}" -gt 0 ] && pass "elastic punch ($label, $np): all $n contactor nodes closed" \
            || fail "elastic punch ($label, $np): $nClosed of $n contactor nodes closed"
        checkBelow "elastic punch ($label, $np): max |p - p_exact|/p_exact" "$dev" "$ptol"
        punchForceChecks "$label, $np" "$F" "$Fb" "$ftol" "$its" "$steps"
        # The effect report names the pair between the two bodies
        if [ "$np" = 8 ]; then
            checkEffect "elastic punch: effect report" "$c" contact:punchBlock touched matters
        fi
    else
        reportFailure "elastic punch run ($label, $np)" "$c"
    fi
    keepOrRemove "$c"
}
deformablePunch 8 1e-6 1e-8 "matching"
deformablePunch 16 1e-6 1e-8 "punch nodes include the block's"
deformablePunch 5 0.35 0.025 "non-matching, coarser punch"
deformablePunch 7 0.35 0.025 "non-matching, coarser punch"
deformablePunch 11 0.15 0.001 "non-matching, finer punch"
deformablePunch 13 0.15 0.001 "non-matching, finer punch"

# (d) two-pass: each side is contactor and target (a second pair with the
#     roles swapped). The force splits between the passes in an uneven
#     nodal pattern, but the total comes closer to the exact one than with
#     one pass on the same non-matching meshes (5, 7 punch elements: -1.9 %
#     single-pass), at nearly the same Newton cost: at most 8 iterations
#     per step (observed 7.5 with 7 punch elements). Two passes press the
#     same points from both sides, so the split of the force between them
#     is not unique: once the force criterion holds, the energy criterion
#     of the predicted second step spends a few line-search iterations in
#     that direction before the solver sees that no step reduces the
#     residual (staticSolver.H; before 2026-11-25 a predicted step was
#     accepted on the force criterion alone)
twoPass()
{
    local np=$1 c F Fb its steps
    c=$(newCase flatPunchDeformable)
    # (the case as stored has nPunch 8: edit only another number)
    [ "$np" = 8 ] || sed -i "s/^nPunch .*/nPunch  $np;/" "$c/system/block/blockMeshDict"
    sed -i 's/^\( *punchBlock .*\)$/\1\n    blockPunch { patch blockTop; targetPatch punchBottom; friction 0; }/' \
        "$c/constant/contactProperties"
    if run "$c"; then
        F=$(summary "$c" punchReaction)
        Fb=$(summary "$c" bottomReaction)
        its=$(summary "$c" newtonIterations)
        steps=$(summary "$c" steps)
        echo "    elastic punch, two-pass ($np punch / 8 block elements): force $F (exact $FD)," \
             "Newton $its iterations in $steps steps"
        punchForceChecks "two-pass, $np" "$F" "$Fb" 0.002 "$its" "$steps" 8.01
    else
        reportFailure "elastic punch run (two-pass, $np)" "$c"
    fi
    keepOrRemove "$c"
}
twoPass 5
twoPass 7
