#!/usr/bin/env bash
# Cook's membrane (BENCHMARKS.md): locking, equilibrium, nearly
# incompressible stability, Newton rate, automatic cutback.
. "$(dirname "$0")/testFunctions"
ref=16.4326     # v(48,52), linear, plane strain (Krysl, NICE-T6 extrapolated)

run()   # run <case>: blockMesh + formFoam, logs in the case
{
    rm -rf "$1/postProcessing"
    (cd "$1" && blockMesh -region solid > log.blockMesh 2>&1 \
             && formFoam > log.formFoam 2>&1)
}

# 1. The tutorial itself: 9/3 on 16x16 within 0.05 % (locking-free; the
#    observed error is 0.011 %, and 0.05 % fails Q9P3 on 4 x 4 and the
#    displacement Q9, which the old 1 % passed), reaction balances the
#    applied shear F = 1
c=$(caseCopy cooksMembrane)
run "$c" || fail "linear Q9P3 run (see $c/log.formFoam)"
q9tip=$(summaryValue "$c" tipDisplacementY)
checkClose "Q9P3 16x16 tip v(48,52)" "$q9tip" $ref 5e-4
checkClose "Q9P3 clamp reaction = -F" "$(summaryValue "$c" clampReactionY)" -1 1e-8

# 2. Displacement-based Q4 locks: below 50% of the reference
foamDictionary -case "$c" -entry elementType -set Q4 \
    "$c/constant/solid/solidProperties" > /dev/null
run "$c" || fail "linear Q4 run"
checkBelow "Q4 16x16 locks" "$(summaryValue "$c" tipDisplacementY)" \
    "$(awk -v r=$ref 'BEGIN { print 0.5*r }')"

# 3. Nearly incompressible limit: nu -> 0.4999999 with 9/3 still converges
#    to the same answer (the limit differs from nu = 0.499975 by 0.003 %;
#    observed error 0.014 %, tolerance 0.05 %)
foamDictionary -case "$c" -entry elementType -set Q9P3 \
    "$c/constant/solid/solidProperties" > /dev/null
# (sed: foamDictionary -set would round the value to 6 digits)
sed -i 's/^\( *nu \).*/\1 0.4999999;/' "$c/constant/solid/solidProperties"
run "$c" || fail "linear Q9P3 nu = 0.4999999 run"
checkClose "Q9P3 nu=0.4999999 tip" "$(summaryValue "$c" tipDisplacementY)" $ref 5e-4
rm -rf "$c"

# 4. Neo-Hookean large deformation: converges; asymptotic Newton rate ~ 2
c=$(caseCopy cooksMembrane/neoHookean)
run "$c" || fail "neo-Hookean run (see $c/log.formFoam)"
tipSteps=$(summaryValue "$c" tipDisplacementY)
checkClose "neo-Hookean reaction = -100" "$(summaryValue "$c" clampReactionY)" -100 1e-6
# (with the tracked pressure of the mixed elements, solidElement.H, and
# the predicted pressures the steps take 2-4 iterations, too few for the
# order from three successive energies, and the end is faster than
# quadratic. Checked instead on the last three update norms of every step
# that has them: the contraction improves at least tenfold from one update
# to the next, (d3/d2)/(d2/d1) <= 0.1, which a linear rate (ratio 1)
# fails and a quadratic end (ratio d2/d1) passes; observed <= 5e-3)
read -r worst nChecked < <(awk '
    /^Step / { flush(); next }
    match($0, /\|dU\| [0-9.eE+-]+/) { d[n++] = substr($0, RSTART + 5, RLENGTH - 5) + 0 }
    function flush(   q) {
        if (n >= 3 && d[n-3] > 0 && d[n-2] > 0) {
            q = (d[n-1]/d[n-2])/(d[n-2]/d[n-3])
            if (q > worst) worst = q
            ++steps
        }
        n = 0
    }
    END { flush(); print (steps ? worst : "none"), steps + 0 }' "$c/log.formFoam")
if awk -v w="$worst" -v n="$nChecked" 'BEGIN { exit !(w != "none" && w <= 0.1 && n >= 3) }'; then
    pass "neo-Hookean Newton ends superlinearly in each of $nChecked steps (largest (d3/d2)/(d2/d1) $worst <= 0.1)"
else
    fail "neo-Hookean Newton end: largest (d3/d2)/(d2/d1) $worst over $nChecked steps (expected <= 0.1, at least 3 steps)"
fi
# The tracked pressure's saving (issue 20): 18 iterations in 6 steps
# (every predicted step in 3), 25 with the pressures at the predicted
# state taken as p_e of the extrapolated displacements (2026-11-28), 35 in
# 7 steps without the tracked pressure
its=$(summaryValue "$c" newtonIterations)
if [ -n "$its" ] && [ "$its" -le 20 ]; then
    pass "neo-Hookean Newton iterations $its <= 20 (25 without the predicted pressures, 35 without the tracked pressure)"
else
    fail "neo-Hookean Newton iterations $its (expected <= 20; 25 without the predicted pressures, 35 without the tracked pressure)"
fi

# 5. The whole load in one step. With the tracked pressure (and the line
#    search taking the mixed system's full steps) Newton converges in 5
#    iterations without a cutback (before: 8 iterations were not enough
#    and the step was cut back); with at most 3 iterations the step must
#    be cut back automatically. Both reach the stepped run's answer.
foamDictionary -case "$c" -entry deltaT -set 1 "$c/system/controlDict" > /dev/null
foamDictionary -case "$c" -entry maxDeltaT -set 1 "$c/system/solidSolution" > /dev/null
foamDictionary -case "$c" -entry maxIterations -set 8 "$c/system/solidSolution" > /dev/null
rm -rf "$c/0."* "$c/1" "$c/postProcessing"
run "$c" || fail "neo-Hookean single-step run"
n=$(summaryValue "$c" cutbacks)
its=$(summaryValue "$c" newtonIterations)
if [ "$n" = 0 ] && [ -n "$its" ] && [ "$its" -le 6 ]; then
    pass "the whole load in one step: $its Newton iterations, no cutback"
else
    fail "the whole load in one step: $its Newton iterations, $n cutbacks (expected <= 6, none)"
fi
checkClose "one-step run tip = stepped run tip" \
    "$(summaryValue "$c" tipDisplacementY)" "$tipSteps" 1e-6
foamDictionary -case "$c" -entry maxIterations -set 3 "$c/system/solidSolution" > /dev/null
rm -rf "$c/0."* "$c/1" "$c/postProcessing"
run "$c" || fail "neo-Hookean single-step run, 3 iterations"
n=$(summaryValue "$c" cutbacks)
checkBelow "large step was cut back automatically (summary cutbacks $n >= 1)" 0 "$n"
checkClose "cut-back run tip = stepped run tip" \
    "$(summaryValue "$c" tipDisplacementY)" "$tipSteps" 1e-6
rm -rf "$c"

# 6. The same membrane in 3D: the mesh extruded one cell thick (the front
#    and back patches of type patch instead of empty, held in z: plane
#    strain), analysisType solid3D. 27/4 hexahedra on the same in-plane
#    mesh are the 9/3 quads times a constant in z, so they reproduce the
#    2D results to round-off (tolerance 1e-6, linear and neo-Hookean);
#    the 8-node hexahedron locks like the 4-node quad.
extrude()   # extrude <case> <elementType>: the 2D case made 3D
{
    sed -i 's/frontAndBack { type empty;/frontAndBack { type patch;/' \
        "$1/system/solid/blockMeshDict"
    sed -i "s/^\( *analysisType \).*/\1 solid3D;/; s/^\( *elementType \).*/\1 $2;/" \
        "$1/constant/solid/solidProperties"
    sed -i 's/frontAndBack *{ type empty; }/frontAndBack { type fixedDisplacement; components (z); }/' \
        "$1/0/solid/D"
    rm -rf "$1"/constant/solid/polyMesh "$1"/[1-9]* "$1"/0.*
}
c=$(caseCopy cooksMembrane)
extrude "$c" Hex27P4
run "$c" || fail "3D Hex27P4 run (see $c/log.formFoam)"
checkClose "Hex27P4 extruded tip = Q9P3 tip" \
    "$(summaryValue "$c" tipDisplacementY)" "$q9tip" 1e-6
checkClose "Hex27P4 clamp reaction = -F" "$(summaryValue "$c" clampReactionY)" -1 1e-8
sed -i 's/^\( *elementType \).*/\1 Hex8;/' "$c/constant/solid/solidProperties"
run "$c" || fail "3D Hex8 run (see $c/log.formFoam)"
checkBelow "Hex8 extruded locks" "$(summaryValue "$c" tipDisplacementY)" \
    "$(awk -v r=$ref 'BEGIN { print 0.5*r }')"
rm -rf "$c"
c=$(caseCopy cooksMembrane/neoHookean)
extrude "$c" Hex27P4
run "$c" || fail "3D neo-Hookean run (see $c/log.formFoam)"
checkClose "Hex27P4 extruded neo-Hookean tip = Q9P3 tip" \
    "$(summaryValue "$c" tipDisplacementY)" "$tipSteps" 1e-6
rm -rf "$c"
