#!/usr/bin/env bash
# Hydraulic bulge (tutorials/hydraulicBulge): the fluid region with the
# hydrostatic model, volume and pressure control, against references that
# do not come from the run itself:
# 1. The tutorial (Allrun: volume control, then pressure control):
#    a. membrane equilibrium at the pole where h ~ 30 mm: p rho/(2 t) + p/2
#       (rho, t measured on the deformed mesh by bulgeCheck.py) equals the
#       Swift flow stress at eps = ln(t0/t) within 3 % (membrane theory
#       neglects bending; measured 1 %);
#    b. the fluid's volume: the volume swept by the blank's lower face
#       (integrated from the nodes) equals (V0 + V_inj) exp(-p/K) - V0
#       within 5e-5 (observed 2.2e-5: the nodes' trapezoidal rule against
#       the exact quadratic edges);
#    c. pole thickness at h = 30 mm between Hill (1950) t0/(1 + (h/a)^2)^2
#       (a = 50: the thinnest estimate) and the uniform cap t0/(1 + (h/a)^2),
#       and within 3 % of Hill with a + r_d = 55 (BENCHMARKS.md: estimates,
#       a converged FE result lies near them, not on them);
#    d. against the converged run of hydraulicBulge.reference (4x finer
#       mesh, 2 elements through the thickness, half the step; a
#       regression check against our own code): p at h = 30, t at h = 30,
#       p_max within 0.15 %, 0.5 % and 0.1 % (observed 0.054 %, 0.21 %,
#       0.024 %);
#    e. volume control passes the pressure maximum (final p < 0.99 p_max);
#       pressure control stops at it (its last p within 0.1 % of p_max;
#       observed 0.046 %: near the limit point the tangent turns singular
#       and the last steps before it fail; 0.009 % before 2026-11-25, when
#       a predicted step was accepted on a loosened force criterion;
#       0.041 % at the case's forceTolerance 1e-3 of 2026-11-28, 0.040 %
#       at its 1e-2);
#    f. a restart from the middle of the run reproduces it (1e-10);
#    g. the summary names the fluid model and the entries the issue asks.
# 2. A dry case builds no fluid: the same blank with the oil replaced by a
#    follower pressure on its lower face (no fluid region) reproduces the
#    pressure-controlled run (pole height at p = 9 MPa within 1e-5:
#    observed 1.9e-6, what two Newton paths converged to forceTolerance
#    1e-8 differ by on this flexible membrane; before 2026-11-25 the two
#    runs took identical iterates and agreed to 1e-8; at the case's
#    forceTolerance 1e-3 of 2026-11-28 they agree to 2e-14, at its 1e-2
#    exactly), and its
#    log and summary show no fluid object and no fluid time.
# 3. Bad input of the fluid region: clear errors naming file and entry.
# 4. The ALE fluid model from the same case against the hydrostatic one,
#    both to t = 0.3 at formFoam's default tolerance (1e-8 / 1e-14), where
#    Newton's quadratic end shows: the observed order from the logs, 2 for
#    the hydrostatic oil and the ALE oil (the tutorial's 1e-2 ends its
#    steps before it: order 1.5 and 1.0 there).
. "$(dirname "$0")/testFunctions"
here=$(cd "$(dirname "$0")" && pwd)

value() { summaryValue "$1" "$2"; }
ref() { awk -v e="$1" '$1 == e { print $2 }' "$here/hydraulicBulge.reference"; }
# lastHistory <case> <column>: the last converged step's value
lastHistory()
{
    awk -v n="$2" 'NR == 1 { for (i = 2; i <= NF; i++) c[$i] = i - 1; next }
                   !/^#/ { v = $c[n] } END { print v }' "$1/postProcessing/history.dat"
}

#------------------------------------------------------------------------------
# 1. The tutorial
c=$(caseCopy hydraulicBulge)
if (cd "$c" && OMP_NUM_THREADS=1 timeout 1800 ./Allrun > log.Allrun 2>&1) \
   && [ -f "$c/postProcessing/summary" ]; then
    # Everything the run made is output git ignores (or Allclean removes):
    # run in the tree, it would leave no untracked file
    untracked=0
    while IFS= read -r f; do
        rel=${f#"$c"/}
        [ -e "$formFoamTop/tutorials/hydraulicBulge/$rel" ] && continue
        git -C "$formFoamTop" check-ignore -q "tutorials/hydraulicBulge/$rel" \
            || { untracked=$((untracked + 1)); echo "    not ignored: $rel"; }
    done < <(find "$c" -type f)
    checkBelow "bulge: files of the run that git would report as untracked" "$untracked" 1
    [ "$(summaryValue "$c" fluidModel)" = hydrostatic ] \
        && pass "bulge: summary fluidModel hydrostatic" \
        || fail "bulge: summary fluidModel is '$(summaryValue "$c" fluidModel)'"
    for e in poleHeight pressureAtPoleHeight30mm maxPressure \
             poleThicknessAtPoleHeight30mm wallTime newtonIterationsPerStep; do
        [ -n "$(value "$c" $e)" ] && pass "bulge: summary has $e" \
            || fail "bulge: summary entry $e missing"
    done
    checkBelow "bulge: pole height 30 mm reached (30 < h)" 30 "$(value "$c" poleHeight)"

    read -r sM sS h rho t < <(python3 "$here/bulgeCheck.py" "$c" membrane 30)
    checkClose "bulge: membrane stress at the pole (h = $h, rho = $rho, t = $t) vs Swift" \
        "$sM" "$sS" 0.03
    read -r swept expected < <(python3 "$here/bulgeCheck.py" "$c" volume)
    checkClose "bulge: volume swept by the blank vs the fluid's volume change" \
        "$swept" "$expected" 5e-5

    t30=$(value "$c" poleThicknessAtPoleHeight30mm)
    checkBelow "bulge: pole thickness at 30 mm above Hill (a = 50, 0.5407)" 0.5407 "$t30"
    checkBelow "bulge: pole thickness at 30 mm below the uniform cap (0.7353)" "$t30" 0.7353
    checkClose "bulge: pole thickness at 30 mm vs Hill (a + r_d = 55)" "$t30" \
        "$(awk 'BEGIN { printf "%.6g", 1/(1 + (30/55)^2)^2 }')" 0.03

    for e in "pressureAtPoleHeight30mm 1.5e-3" "poleThicknessAtPoleHeight30mm 5e-3" "maxPressure 1e-3"; do
        set -- $e
        checkClose "bulge: $1 vs the converged 4x finer run (regression, own code)" \
            "$(value "$c" $1)" "$(ref $1)" $2
    done

    pMax=$(value "$c" maxPressure)
    checkBelow "bulge: volume control passes the maximum (final p < 0.99 p_max)" \
        "$(value "$c" pressure)" "$(calc '0.99*p' p="$pMax")"
    if [ -f "$c/pressureControl/postProcessing/history.dat" ] \
       && grep -q "no convergence for the step" "$c/pressureControl/log.formFoam"; then
        checkClose "bulge: pressure control stops at the maximum" \
            "$(lastHistory "$c/pressureControl" pressure)" "$pMax" 1e-3
    else
        fail "bulge: the pressure-controlled run did not stop at the maximum"
    fi

    # Restart from a written time in the middle (solid, material history,
    # contact and oil pressure state, and the run state: step size and the
    # extrapolating predictor's increments) to the next written time
    # reproduces the continuous run to 1e-10: the same steps from the same
    # state (a lost material history or contact state would show at the
    # percent level, a lost predictor at 1e-5). Observed: identical. (Until
    # 2026-11-27 a case without a processSchedule restarted at the rounded
    # directory time and without its predictor; the steps converged to
    # round-off then hid it at 1e-10, the look-ahead of staticSolver.H
    # showed it at 1e-9.)
    r=$(mktemp -d "${TMPDIR:-/tmp}/formFoamTest.XXXXXX")
    cp -r "$c/." "$r/"
    rm -rf "$r/pressureControl"
    tr=$(ls -d "$r"/0.5* | head -1); tr=${tr##*/}
    te=$(ls -d "$r"/0.6* | head -1); te=${te##*/}
    # The step's exact end time (directory names are rounded to
    # timePrecision): the restart must stop where the continuous run's
    # step ended
    te=$(awk -v t="$te" 'NR > 1 && ($1 - t)^2 < 1e-12 { print $1; exit }' \
        "$c/postProcessing/history.dat")
    sed -i "s/^startTime .*/startTime       $tr;/; s/^endTime .*/endTime         $te;/" \
        "$r/system/controlDict"
    # (the entries at h = 30 mm are not reached by then)
    sed -i '/at (poleHeight 30)/d; /poleThicknessAtPoleHeight30mm/d' "$r/system/solidSolution"
    if [ -n "$tr" ] && [ -n "$te" ] \
       && (cd "$r" && OMP_NUM_THREADS=1 formFoam > log.restart 2>&1) \
       && grep -q "Restarting from the state written at time $tr" "$r/log.restart"; then
        for e in poleHeight pressure; do
            checkClose "bulge: restart at t = $tr: $e at t = $te vs the continuous run" \
                "$(value "$r" $e)" \
                "$(awk -v t="$te" -v n="$e" 'NR == 1 { for (i = 2; i <= NF; i++) c[$i] = i - 1; next }
                    $1 == t { print $c[n] }' "$c/postProcessing/history.dat")" 1e-10
        done
        # the restored predictor: the first step after the restart starts
        # from the extrapolated increment, as in the continuous run
        if grep -m1 "iter  0" "$r/log.restart" | grep -q predicted; then
            pass "bulge: restart at t = $tr: the first step starts from the restored predictor"
        else
            fail "bulge: restart at t = $tr: the first step does not start from the predictor (see $r/log.restart)"
        fi
    else
        fail "bulge: restart at t = '$tr' (see $r/log.restart)"
    fi
else
    fail "bulge: tutorial run (see $c/log.Allrun, $c/log.formFoam)"
    tail -15 "$c/log.formFoam" | sed 's/^/    | /'
fi

#------------------------------------------------------------------------------
# 2. Dry: the oil replaced by a follower pressure (no fluid region)
# poleHeightOnly <solidSolution>: the summary reduced to the pole height
# (the 30 mm entries are not reached at 9 MPa)
poleHeightOnly()
{
    python3 - "$1" <<'PYTHON'
import re, sys
p = sys.argv[1]
s = open(p).read()
s = s[:re.search(r'^summary', s, re.M).start()] + '''summary
{
    poleHeight { type displacement; point (0 1 0); component z; }
}
'''
open(p, 'w').write(s)
PYTHON
}
d=$(caseCopy hydraulicBulge)
(
    cd "$d" || exit 1
    sed -i 's/^regions .*/regions ( solid (blank) );/' constant/regionProperties
    rm -rf constant/oil
    sed -i 's/^    bottom      { type free; }.*/    bottom      { type pressure; pressure table ((0 0) (1 11)); }/' \
        0/blank/D
    sed -i 's/^endTime .*/endTime         0.8181818181818181;/' system/controlDict
    poleHeightOnly system/solidSolution
    blockMesh -region blank > log.blockMesh 2>&1 && OMP_NUM_THREADS=1 formFoam > log.formFoam 2>&1
) || { fail "bulge dry: run (see $d/log.formFoam)"; tail -15 "$d/log.formFoam" | sed 's/^/    | /'; }
p=$(mktemp -d "${TMPDIR:-/tmp}/formFoamTest.XXXXXX")
cp -r "$formFoamTop/tutorials/hydraulicBulge/." "$p/"
(
    cd "$p" || exit 1
    ./Allclean > /dev/null 2>&1
    sed -i 's/^injectedVolume[[:space:]].*;/pressure        table ((0 0) (1 11));/' \
        constant/oil/fluidProperties
    sed -i 's/^endTime .*/endTime         0.8181818181818181;/' system/controlDict
    poleHeightOnly system/solidSolution
    blockMesh -region blank > log.blockMesh 2>&1 && OMP_NUM_THREADS=1 formFoam > log.formFoam 2>&1
) || { fail "bulge pressure control to 9 MPa: run (see $p/log.formFoam)"; }
if [ -f "$d/postProcessing/summary" ] && [ -f "$p/postProcessing/summary" ]; then
    checkClose "bulge dry: follower pressure vs the oil cavity at 9 MPa (pole height)" \
        "$(value "$d" poleHeight)" "$(value "$p" poleHeight)" 1e-5
    [ "$(summaryValue "$d" fluidModel)" = none ] \
        && pass "bulge dry: summary fluidModel none" \
        || fail "bulge dry: summary fluidModel '$(summaryValue "$d" fluidModel)'"
    grep -q "fluid: none declared (not built)" "$d/log.formFoam" \
        && pass "bulge dry: the scene builds no fluid" \
        || fail "bulge dry: the scene line 'fluid: none declared' is missing"
    ft=$(awk '$1 == "fluid" && NF == 2 { print $2 }' "$d/log.formFoam")
    [ "$ft" = 0 ] && pass "bulge dry: fluid time 0" \
        || fail "bulge dry: fluid time '$ft', not 0"
    mt=$(awk '$1 == "mesh" && $2 == "motion" { print $3 }' "$d/log.formFoam")
    [ "$mt" = 0 ] && pass "bulge dry: mesh motion time 0" \
        || fail "bulge dry: mesh motion time '$mt', not 0"
fi

#------------------------------------------------------------------------------
# 4. The ALE fluid model from the same case (the one-word switch in
#    constant/oil/fluidProperties): a coarse oil mesh (2 + 16 cells
#    radially, 6 deep), injection to t = 0.3 (pole height about 12.6 mm),
#    against the hydrostatic model on the same blank. The oil is slow
#    (timeScale 60 s: |u| < 30 mm/s), so its pressure is uniform to 1e-5
#    and the models differ only by the fluid mesh's polygonal boundary
#    (chords of the bulged blank) and its wedge faces; stated tolerance
#    0.2 % on pole height, pressure and pole thickness (measured: 0.08 %,
#    0.004 %, 0.014 %).
# shortCase [ALE]: a copy run to t = 0.3 at formFoam's default tolerances
# (the case's entries removed), meshed; with ALE the oil on the coarse
# mesh. Prints its path
shortCase()
{
    local x
    x=$(caseCopy hydraulicBulge)
    (
        cd "$x" || exit 1
        sed -i 's/^endTime .*/endTime 0.3;/' system/controlDict
        sed -i '/at (poleHeight 30)/d; /of (poleTopAt30/d' system/solidSolution
        sed -i '/^forceTolerance /d; /^energyTolerance /d' system/solidSolution
        blockMesh -region blank > log.blockMesh 2>&1
        if [ "${1:-}" = ALE ]; then
            sed -i 's/^fluidModel .*/fluidModel ALENavierStokes;/' constant/oil/fluidProperties
            sed -i 's/^nPort .*/nPort 2;/; s/^nOut .*/nOut 16;/; s/^nz .*/nz 6;/' system/oil/blockMeshDict
            blockMesh -region oil > log.blockMesh.oil 2>&1
        fi
    )
    echo "$x"
}
# againstHydrostatic <label> <case>: pole height, pressure and pole
# thickness at t = 0.3 against the hydrostatic run $hyd, within 0.2 %
againstHydrostatic()
{
    local e what
    for e in poleHeight pressure poleThickness; do
        case $e in
            poleHeight) what="pole height" ;;
            pressure) what="pressure" ;;
            poleThickness) what="pole thickness" ;;
        esac
        checkClose "$1 vs hydrostatic: $what at t = 0.3" \
            "$(value "$2" $e)" "$(value "$hyd" $e)" 0.002
    done
}
ale=$(shortCase ALE)
hyd=$(shortCase)
grep -q "^forceTolerance\|^energyTolerance" "$ale/system/solidSolution" "$hyd/system/solidSolution" \
    && fail "bulge ALE: the case's tolerances could not be removed (system/solidSolution)"
(cd "$ale" && OMP_NUM_THREADS=1 timeout 900 formFoam > log.formFoam 2>&1)
(cd "$hyd" && OMP_NUM_THREADS=1 timeout 300 formFoam > log.formFoam 2>&1)
if grep -q '^End' "$ale/log.formFoam" && grep -q '^End' "$hyd/log.formFoam"; then
    pass "bulge ALE: ran to t = 0.3"
    [ "$(summaryValue "$ale" fluidModel)" = ALENavierStokes ] \
        && pass "bulge ALE: summary fluidModel ALENavierStokes" \
        || fail "bulge ALE: summary fluidModel is '$(summaryValue "$ale" fluidModel)'"
    againstHydrostatic "bulge ALE" "$ale"
    # The effect report: the slow oil loads the blank with a uniform
    # pressure, so the hydrostatic model would do; the hydrostatic run has
    # no fluid measures (a uniform pressure is its model); the blank's
    # plastic flow matters in both
    checkEffect "bulge ALE: effect report" "$ale" fluid pressureSpread negligible
    checkEffect "bulge ALE: effect report" "$ale" fluid viscousTraction negligible
    checkEffect "bulge: effect report" "$hyd" plasticity plasticDissipation matters
    [ -z "$(effectValue "$hyd" fluid pressureSpread)" ] && [ -f "$hyd/postProcessing/effects" ] \
        && pass "bulge hydrostatic: the effect report has no fluid measures" \
        || fail "bulge hydrostatic: effect report missing or with fluid measures"
    q=$(newtonOrder "$hyd/log.formFoam")
    checkBelow "bulge: Newton order (median over the steps) above 1.8" 1.8 "$q"
    q=$(newtonOrder "$ale/log.formFoam")
    checkBelow "bulge ALE: Newton order $q (2 - q)" "$(calc '2 - q' q="$q")" 0.3
    # The time per effect: the mesh motion, part of the fluid's time
    read -r ft mt < <(awk '$1 == "fluid" && NF == 2 { f = $2 }
        $1 == "mesh" && $2 == "motion" { m = $3 } END { print f, m }' "$ale/log.formFoam")
    awk -v f="$ft" -v m="$mt" 'BEGIN { exit !(m != "" && f != "" && m > 0 && m < f) }' \
        && pass "bulge ALE: time per effect: mesh motion $mt s of the fluid's $ft s" \
        || fail "bulge ALE: mesh motion time '$mt' not within the fluid's '$ft'"
    grep -q "interface: [0-9]* fluid faces" "$ale/log.formFoam" \
        && pass "bulge ALE: the scene prints the interface" \
        || fail "bulge ALE: no interface line in the scene"
else
    fail "bulge ALE: formFoam failed"; tail -20 "$ale/log.formFoam" "$hyd/log.formFoam"
fi

#------------------------------------------------------------------------------
# 2b. Fast injection (issue 24): the same 200 cm^3 in one second
#    (timeScale 1) instead of a minute: the oil enters at Q/A = 2e5/(pi 6^2)
#    = 1768 mm/s, face Peclet numbers reach about 200 on this mesh (2 at
#    timeScale 60).
#    - steady momentum (the case's ddtSchemes): no steady flow Newton can
#      reach from rest; the run must stop cleanly, name the cause (the face
#      Peclet number, ddtSchemes Euler) and never accept a step with the oil
#      at garbage speeds (before 2026-11-29 it accepted steps at 130 m/s and
#      16 km/s through a force criterion measured against the iterate's own
#      inflated fluid scale, and a near-equilibrium rule whose premise, a
#      small update, was not checked);
#    - transient (ddtSchemes Euler): converges; the bulge is the quasi-static
#      one (the oil's dynamic pressure rho u^2/2 ~ 1.4e-3 MPa), so it must
#      agree with the hydrostatic model at t = 0.3 within the 0.2 % of
#      section 2 (measured 2026-11-29: pole height -0.065 %, pressure
#      +0.024 %, thickness +0.013 %), with the oil never faster than 4 times
#      the inflow speed (observed: 1.08 times).
uIn=$(awk 'BEGIN { printf "%.12g", 2e5/(atan2(0, -1)*36) }')
maxSpeed() { sed -n 's/.*fluid oil: max |U| = \([^ ,]*\)[ ,].*/\1/p' "$1" | sort -g | tail -1; }
fast=$(shortCase ALE)
fastSteady=$(shortCase ALE)
sed -i 's/^timeScale .*/timeScale 1;/' "$fast/constant/oil/fluidProperties" \
    "$fastSteady/constant/oil/fluidProperties"
sed -i 's/default steadyState;/default Euler;/' "$fast/system/oil/fvSchemes"
# (the steady run gives up sooner: at most 5 cutbacks)
echo "maxCutbacks 5;" >> "$fastSteady/system/solidSolution"
(cd "$fast" && OMP_NUM_THREADS=1 timeout 600 formFoam > log.formFoam 2>&1)
(cd "$fastSteady" && OMP_NUM_THREADS=1 timeout 600 formFoam > log.formFoam 2>&1)
if grep -q '^End' "$fast/log.formFoam" && [ -f "$hyd/postProcessing/summary" ]; then
    pass "bulge ALE, fast injection, transient: ran to t = 0.3"
    againstHydrostatic "bulge ALE fast (Euler)" "$fast"
    checkBelow "bulge ALE fast (Euler): largest oil speed below 4 times the inflow ($uIn mm/s)" \
        "$(maxSpeed "$fast/log.formFoam")" "$(calc '4*u' u="$uIn")"
else
    fail "bulge ALE, fast injection, transient: formFoam failed"; tail -20 "$fast/log.formFoam"
fi
if grep -q '^End' "$fastSteady/log.formFoam"; then
    fail "bulge ALE, fast injection, steady: ran to the end (a steady flow at face Peclet 200 was not expected to converge: check the log)"
else
    grep -q "no convergence for the step" "$fastSteady/log.formFoam" \
        && pass "bulge ALE, fast injection, steady: stops with no convergence" \
        || { fail "bulge ALE, fast injection, steady: no clean stop"; tail -20 "$fastSteady/log.formFoam"; }
    grep -q "face Peclet numbers of .*ddtSchemes { default Euler; } in system/oil/fvSchemes" \
        "$fastSteady/log.formFoam" \
        && pass "bulge ALE, fast injection, steady: the stop names the Peclet number and the transient model" \
        || fail "bulge ALE, fast injection, steady: the stop does not say why"
    s=$(maxSpeed "$fastSteady/log.formFoam")
    checkBelow "bulge ALE, fast injection, steady: no accepted step with the oil above 4 times the inflow" \
        "${s:-0}" "$(calc '4*u' u="$uIn")"
fi
rm -rf "$fast" "$fastSteady"
rm -rf "$ale" "$hyd"

#------------------------------------------------------------------------------
# 3. Bad input
base=$(caseCopy hydraulicBulge)
(cd "$base" && blockMesh -region blank > log.blockMesh 2>&1) || fail "bulge: blockMesh"
fp=constant/oil/fluidProperties
tryCase "fluid: no interface with a solid" \
    "Entry 'interface' missing in .*fluidProperties.*needs an interface" \
    "foamDictionary -entry interface -remove $fp > /dev/null"
tryCase "fluid: interface patch unknown" \
    "Entry 'interface' in .*fluidProperties.*'botom' is not a patch of solid region 'blank'" \
    "sed -i 's/^interface .*/interface (botom);/' $fp"
tryCase "fluid: interface on the wedge (front/back) patch" \
    "Entry 'interface' in .*fluidProperties.*'front' is an empty or wedge patch of solid region 'blank'" \
    "sed -i 's/^interface .*/interface (front);/' $fp"
tryCase "fluid: non-positive bulk modulus" \
    "Entry 'bulkModulus' in .*fluidProperties.*positive" \
    "sed -i 's/^bulkModulus .*/bulkModulus -1500;/' $fp"
tryCase "fluid: zero initial volume" \
    "Entry 'initialVolume' in .*fluidProperties.*positive" \
    "sed -i 's/^initialVolume .*/initialVolume 0;/' $fp"
tryCase "fluid: unknown fluid model" \
    "Entry 'fluidModel' in .*fluidProperties.*unknown model 'hydrostatics'" \
    "sed -i 's/^fluidModel .*/fluidModel hydrostatics;/' $fp"
tryCase "fluid: ALE fluid without its mesh" \
    "Fluid region 'oil' \\(constant/oil/fluidProperties, fluidModel ALENavierStokes\\) has no mesh.*run blockMesh -region oil" \
    "sed -i 's/^fluidModel .*/fluidModel ALENavierStokes;/' $fp"
tryCase "fluid: ALE fluid without the fluid side of the interface" \
    "Entry 'fluidInterface' missing or empty in constant/oil/fluidProperties.*interface with solid region 'blank'" \
    "sed -i 's/^fluidModel .*/fluidModel ALENavierStokes;/; /^fluidInterface /d' $fp && blockMesh -region oil > /dev/null 2>&1"
tryCase "fluid: ALE wedge about another axis than the blank's" \
    "Fluid region 'oil' \\(constant/oil/fluidProperties\\) and solid region 'blank'.*: the fluid wedge's axis is not the solid's" \
    "sed -i 's/^fluidModel .*/fluidModel ALENavierStokes;/' $fp && blockMesh -region oil > /dev/null 2>&1 && transformPoints -region oil -rollPitchYaw '(0 0 90)' > /dev/null 2>&1"
tryCase "fluid: both volume and pressure control" \
    "needs exactly one of 'injectedVolume'.*'pressure'" \
    "echo 'pressure constant 1;' >> $fp"
tryCase "fluid: mistyped entry" \
    "Unknown entry 'bulkModulu' in dictionary .*fluidProperties" \
    "sed -i 's/^bulkModulus /bulkModulu /' $fp"
tryCase "fluid: missing fluidProperties" \
    "cannot find file.*constant/oil/fluidProperties" \
    "rm $fp"
tryCase "fluid: unknown solid region" \
    "Entry 'solidRegion' in .*fluidProperties.*unknown solid region 'sheet'" \
    "echo 'solidRegion sheet;' >> $fp"
tryCase "fluid: summary 'at' never reached" \
    "'poleHeight' never reached 300" \
    "sed -i 's/at (poleHeight 30); }/at (poleHeight 300); }/; s/^endTime .*/endTime 0.04;/' system/solidSolution system/controlDict"
tryCase "fluid: summary type without a fluid" \
    "Unknown summary type 'fluidPressure'" \
    "sed -i 's/^regions .*/regions ( solid (blank) );/' constant/regionProperties"

# the scratch copies (KEEP=1 keeps them)
[ -n "${KEEP:-}" ] || rm -rf "$c" "${r:-}" "$d" "$p" "$base"
