#!/usr/bin/env bash
# The S-rail tutorial (tutorials/sRail: a hat channel with an S-bend in
# plan drawn 37 mm deep from MITC4 shells, tools released, springback) on
# a reduced mesh, 30 x 26 elements instead of 60 x 50, with its Allrun.
# Checks:
#  - against the recorded run of this configuration (tests/cases/
#    sRail.reference, with provenance): punch force, thinnest point,
#    largest major strain, flange draw-in, springback displacement and
#    the released side wall's angle within the tolerances given there (a
#    regression guard; the tutorial's README compares with its mesh);
#  - force control: the holder carries its 10 kN (1e-9);
#  - the point symmetry of the part (a half turn about the vertical
#    through the middle of the S maps tools, blank, mesh and the
#    orthotropic steel onto themselves; the pins of the forming step are
#    symmetric, those of springback statically determinate): the two side
#    walls at the middle of the S have the same angle to the face formed
#    and released, and the same twist (1e-5 deg; observed 7e-8), and the
#    flange edges at the middle of the S draw in alike (1e-8 relative;
#    observed 1e-10): the Newton tolerance, not the model. An error in the
#    tools' left or right turns (pathProfile) or in the map of the blank
#    breaks it;
#  - the springback step converges without a cutback (2 before the
#    elastic tangent on the yield surface, returnMapping.C) and the
#    released punch carries no force;
#  - Newton converges quadratically at the end of the steps (observed
#    order, median over the steps, at least 1.6; observed 1.74: the
#    last energies of many steps sit on the round-off floor, 1e-16 to
#    1e-14, of 4000 unknowns, where the order reads low; a wrong tangent
#    or linear convergence gives about 1);
#  - the plots exist (punchForce.png, formingLimit.png, thickness.png,
#    springback.png, outline.png), and the formed blank's outline
#    (postProcessing/outline.dat, from the mesh points: an output of its
#    own) is point symmetric (1e-5 mm; observed 2e-8).
. "$(dirname "$0")/testFunctions"
here=$(cd "$(dirname "$0")" && pwd)
c=$(caseCopy sRail)
summary() { summaryValue "$c" "$1"; }

# (the repository's Allrun edits a copy: -cells on the copy itself is refused)
if timeout 2400 "$formFoamTop/tutorials/sRail/Allrun" -case "$c" -cells 30 26 > "$c/log.Allrun" 2>&1 \
    && [ -f "$c/postProcessing/summary" ]
then
    [ -f "$here/sRail.reference" ] || fail "sRail.reference missing: its checks cannot run"
    while read -r name value tol; do
        case $name in ''|'#'*) continue ;; esac
        checkClose "S-rail $name vs the recorded run" "$(summary "$name")" "$value" "$tol"
    done < "$here/sRail.reference"
    checkClose "S-rail: the holder carries 10 kN" "$(summary holderForce)" 10000 1e-9
    for q in wallAngle%Formed wallAngle% sideWallTwist%; do
        left=${q/\%/Left} right=${q/\%/Right}
        checkBelow "S-rail point symmetry: $left - $right (deg)" \
            "$(calc 'abs(a - b)' a="$(summary "$left")" b="$(summary "$right")")" 1e-5
    done
    checkClose "S-rail point symmetry: the flange edges at the middle of the S draw in alike" \
        "$(summary drawInMiddleLeft)" "$(summary drawInMiddleRight)" 1e-8
    checkBelow "S-rail: cutbacks in the springback step (t > 1)" \
        "$(awk '/^Step .*deltaT =/ { t = $5 + 0 } /cutting back/ && t > 1 { n++ } END { print n + 0 }' \
           "$c/log.formFoam")" 1
    checkBelow "S-rail: after springback (t = 2) the released punch carries no force (N)" \
        "$(awk 'NR == 1 { for (i = 2; i <= NF; i++) if ($i == "punchForceMax") k = i - 1; next }
                !/^#/ { t = $1; f = $k } END { if (k && t == 2) print (f < 0 ? -f : f) }' \
           "$c/postProcessing/history.dat")" 1e-9
    order=$(newtonOrder "$c/log.formFoam")
    checkBetween "S-rail: Newton's order at the end of the steps (median)" "$order" 1.6 100
    echo "    S-rail (30 x 26): $(summary newtonIterationsPerStep) Newton its/step," \
         "$(summary cutbacks) cutbacks, forming $(summary formingWallTime) s," \
         "springback $(summary springbackWallTime) s"
    [ -f "$c/punchForce.png" ] && [ -f "$c/formingLimit.png" ] && [ -f "$c/thickness.png" ] \
        && [ -f "$c/springback.png" ] && [ -f "$c/outline.png" ] \
        && pass "S-rail plots written (punchForce, formingLimit, thickness, springback, outline)" \
        || fail "S-rail plots missing in $c (see log.plot*)"
    # the blank's outline at the end of forming is point symmetric too:
    # the point that starts at -(x0, y0) ends at -(x, y) (released, the
    # springback pins are not symmetric: the part moves as a rigid body)
    checkBelow "S-rail point symmetry of the formed blank's outline (mm)" \
        "$(awk 'function f(v,  s) { s = sprintf("%.3f", v); return s == "-0.000" ? "0.000" : s }
             !/^#/ && NF >= 4 { k = f($1) " " f($2); n++; x[k] = $3; y[k] = $4 }
             END { if (n < 4) { print "nan"; exit }
                   for (k in x) { split(k, p, " ")
                       m = f(-p[1]) " " f(-p[2])
                       if (!(m in x)) { print "nan"; exit }
                       d = x[k] + x[m]; if (d < 0) d = -d; if (d > e) e = d
                       d = y[k] + y[m]; if (d < 0) d = -d; if (d > e) e = d }
                   printf "%.3g\n", e }' "$c/postProcessing/outline.dat")" 1e-5
else
    fail "S-rail tutorial run (see $c/log.Allrun, $c/log.formFoam)"
    tail -15 "$c/log.formFoam" 2>/dev/null | sed 's/^/    | /'
fi
[ -n "${KEEP:-}" ] && echo "    kept $c" || rm -rf "$c"
