#!/usr/bin/env bash
# The hemming tutorial (tutorials/hemming: flanging, pre-hemming, final
# hemming, springback; two deformable bodies, rigid tools, implicit
# dynamics with the trapezoidal rule), run as it ships. Checks:
#  - geometry the tools impose: the flange turned by 90 deg against the
#    pad's wall (3 deg: the steel wipes it up to mid-height, the upper
#    half leans out by 2.2 deg), by 135 deg along the pre-hemming tool's
#    45 deg face (5 %: it springs back off the face by 5.7 deg), by 180
#    deg when hemmed flat (1 deg); a closed hem wraps
#    the inner panel's edge, so the hem edge stands t_outer + t_inner/2 =
#    1.15 mm beyond it (5 %: the bend's inner radius is at least
#    t_inner/2);
#  - the run against its recorded values (tests/cases/hemming.reference,
#    with provenance; a regression check against our own code): roll-in,
#    gaps, tool forces, flange angles;
#  - the energy balance of the dynamic stages: the trapezoidal rule
#    conserves it (the scheme's dissipation below 1e-6 of the work);
#  - Newton cost is reported (iterations per step, most in a step).
. "$(dirname "$0")/testFunctions"
here=$(cd "$(dirname "$0")" && pwd)
c=$(caseCopy hemming)
summary() { summaryValue "$c" "$1"; }

if (cd "$c" && timeout 1800 ./Allrun > log.Allrun 2>&1) && [ -f "$c/postProcessing/summary" ]; then
    checkClose "flange turned 90 deg by flanging" "$(summary flangeAngleFlanged)" 90 0.034
    checkClose "flange turned 135 deg by pre-hemming (45 deg tool face)" "$(summary flangeAnglePreHemmed)" 135 0.05
    checkClose "flange turned 180 deg by final hemming" "$(summary flangeAngleHemmed)" 180 0.0056
    checkClose "closed hem: hem edge t_o + t_i/2 beyond the inner edge" "$(summary gapHemmed)" 1.15 0.05
    # Recorded run: name value relative-tolerance per line
    [ -f "$here/hemming.reference" ] || fail "hemming.reference missing: its checks cannot run"
    while read -r name value tol; do
        case $name in ''|'#'*) continue ;; esac
        checkClose "hemming $name vs recorded run (regression, own code)" "$(summary "$name")" "$value" "$tol"
    done < "$here/hemming.reference"
    read -r wext diss < <(awk '!/^#/ { w = $4; d = $5 } END { print w, d }' "$c/postProcessing/energy.dat")
    checkBelow "hemming: energy dissipated by the trapezoidal rule / external work" \
        "$(calc 'abs(d/w)' w="$wext" d="$diss")" 1e-6
    echo "    hemming: $(summary newtonIterationsPerStep) Newton iterations per step" \
         "at most $(summary maxIterationsInAStep) in a step," \
         "$(summary cutbacks) cutbacks, $(summary steps) steps, wall time $(summary wallTime) s"
    [ -f "$c/profiles.png" ] && [ -f "$c/toolForces.png" ] \
        && pass "hemming plots written (profiles.png, toolForces.png)" \
        || fail "hemming plots missing in $c (see log.plotProfiles, log.plotForces)"
else
    fail "hemming tutorial run (see $c/log.Allrun, $c/log.formFoam)"
    tail -15 "$c/log.formFoam" 2>/dev/null | sed 's/^/    | /'
fi
[ -n "${KEEP:-}" ] && echo "    kept $c" || rm -rf "$c"
