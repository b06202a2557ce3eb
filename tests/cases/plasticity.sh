#!/usr/bin/env bash
# Plasticity in the u/p elements at case level:
# 1. Prandtl's smooth flat punch on a perfectly plastic block (plane strain,
#    von Mises, k = sigma_y/sqrt(3)): limit pressure (2 + pi) k (Prandtl
#    1920; e.g. Hill, The Mathematical Theory of Plasticity (1950) ch. VIII).
#    The 9/3 u/p element gives the same limit load on refinement, close to
#    Prandtl's; the 4-node displacement element (Q4) locks under plastic
#    incompressibility and overshoots. Punch indentation 2.25 % of the
#    half-width, where the load has levelled off.
# 2. One load step of log strain 0.5 (plane-strain tension of a block,
#    Swift hardening) converges, and the force matches the homogeneous
#    solution (incompressible plastic flow: sigma = 2/sqrt(3) sigma_y(eps),
#    eps = 2/sqrt(3) * 0.5, width 1/lambda; elastic strains neglected);
#    the effect report says plasticity matters.
# 3. The block stretched elastically: the effect report says the run
#    stayed elastic.
. "$(dirname "$0")/testFunctions"
prandtl=$(awk 'BEGIN { printf "%.10g", (2 + atan2(0, -1))/sqrt(3) }')

punch()   # punch <element> <n>: prints the limit pressure
{
    local d
    d=$(mktemp -d "${TMPDIR:-/tmp}/formFoamPunch.XXXXXX")
    cp -r "$(dirname "$0")/prandtlPunch/." "$d/"
    # (the case as stored is Q9P3 with n = 4: edit only what differs)
    [ "$2" = 4 ] || sed -i "s/^n   4;/n   $2;/; s/^nr  8;/nr  $((2*$2));/; s/^ny  12;/ny  $((3*$2));/" \
        "$d/system/block/blockMeshDict"
    [ "$1" = Q9P3 ] || sed -i "s/elementType     Q9P3;/elementType     $1;/" "$d/constant/block/solidProperties"
    (cd "$d" && blockMesh -region block > log.blockMesh 2>&1 && formFoam > log.formFoam 2>&1) \
        && summaryValue "$d" punchPressure
    [ -z "${3:-}" ] || cp "$d/log.formFoam" "$3"
    rm -rf "$d"
}
punchLog=$(mktemp "${TMPDIR:-/tmp}/formFoamPunchLog.XXXXXX")
p4=$(punch Q9P3 4 "$punchLog")
p8=$(punch Q9P3 8)
q4=$(punch Q4 4)
q8=$(punch Q4 8)
echo "    Prandtl (2 + pi) k = $prandtl"
echo "    Q9P3: n = 4 $p4, n = 8 $p8;  Q4: n = 4 $q4, n = 8 $q8"
# Newton converges quadratically in elastic-plastic flow (consistent
# tangent of the return mapping, the log-strain kinematics and the element)
rate=$(newtonOrder "$punchLog")
if awk -v q="$rate" 'BEGIN { exit !(q != "" && q != "none" && q > 1.6 && q < 2.6) }'; then
    pass "punch (plastic flow) Newton convergence order $rate (quadratic: ~2)"
else
    fail "punch (plastic flow) Newton convergence order $rate (expected ~2)"
fi
rm -f "$punchLog"
# the limit load converges from above (observed: +4.1 % at n = 4, +2.8 %
# at n = 8): it falls on refinement, by at most 2 %, and lies within 4 %
# above Prandtl's
checkBetween "Q9P3 limit pressure falls on refinement, by at most 2 % (n 4 -> 8)" \
    "$p8" "$(calc '0.98*p' p="$p4")" "$p4"
checkBetween "Q9P3 limit pressure above Prandtl, by at most 4 % (n = 8)" \
    "$p8" "$prandtl" "$(awk -v p="$prandtl" 'BEGIN { printf "%.10g", 1.04*p }')"
checkBelow "Q4 locks: Prandtl + 10 % below its pressure (n = 4)" \
    "$(awk -v p="$prandtl" 'BEGIN { printf "%.10g", 1.1*p }')" "$q4"
checkBelow "Q4 locks: still above Q9P3 by 5 % at n = 8" \
    "$(calc '1.05*p' p="$p8")" "$q8"

# 2. A log strain of 0.5 in one step: single 9/3 element in plane-strain
#    tension (bottom fixed in y, left in x, top pulled to stretch e^0.5)
d=$(mktemp -d "${TMPDIR:-/tmp}/formFoamBigStep.XXXXXX")
cp -r "$(dirname "$0")/prandtlPunch/." "$d/"
cat > "$d/system/block/blockMeshDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ((0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1));
blocks (hex (0 1 2 3 4 5 6 7) (1 1 1) simpleGrading (1 1 1));
boundary
(
    top    { type patch; faces ((3 7 6 2)); }
    bottom { type patch; faces ((0 1 5 4)); }
    left   { type patch; faces ((0 4 7 3)); }
    right  { type patch; faces ((1 2 6 5)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
DICT
lambda=$(awk 'BEGIN { printf "%.15g", exp(0.5) }')
cat > "$d/0/block/D" <<DICT
FoamFile { version 2.0; format ascii; class volVectorField; object D; }
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    top    { type fixedDisplacement; components (y); displacement table ((0 (0 0 0)) (1 (0 $(awk -v l="$lambda" 'BEGIN { printf "%.15g", l - 1 }') 0))); }
    bottom { type fixedDisplacement; components (y); }
    left   { type fixedDisplacement; components (x); }
    right  { type free; }
    frontAndBack { type empty; }
}
DICT
sed -i 's/hardening   { type perfect; sigmaY0 1; }/hardening { type swift; K 500; eps0 0.01; n 0.25; }/; s/E           1000;/E           200000;/' \
    "$d/constant/block/solidProperties"
sed -i 's/^deltaT .*/deltaT          1;/' "$d/system/controlDict"
sed -i 's/punchPressure/topForce/; s/patch       punch;/patch       top;/; s/scale       -1;/scale       1;/' \
    "$d/system/solidSolution"
(cd "$d" && blockMesh -region block > log.blockMesh 2>&1 && formFoam > log.formFoam 2>&1) \
    || fail "log strain 0.5 in one step (see $d/log.formFoam)"
checkBelow "log strain 0.5 in one step: no cutback" "$(summaryValue "$d" cutbacks)" 1
ref=$(awk -v l="$lambda" 'BEGIN { e = 2/sqrt(3)*0.5; printf "%.10g", 2/sqrt(3)*500*(0.01 + e)^0.25/l }')
# observed -0.12 % (the reference neglects the elastic strains)
checkClose "log strain 0.5 in one step: force vs homogeneous solution" \
    "$(summaryValue "$d" topForce)" "$ref" 0.005
echo "    one-step Newton iterations: $(summaryValue "$d" newtonIterations)"
checkEffect "log strain 0.5: effect report" "$d" plasticity plasticDissipation matters

# 3. The same block stretched by 1e-4 (the Swift yield strain is
#    500 x 0.01^0.25/E = 7.9e-4) stays elastic: the effect report says so
#    (no plastic dissipation at all, verdict negligible)
for t in "$d"/[0-9]*; do [ "$(basename "$t")" = 0 ] || rm -rf "$t"; done
rm -rf "$d/postProcessing" "$d/VTK"
sed -i "s/displacement table ((0 (0 0 0)) (1 (0 [^ ]* 0)))/displacement table ((0 (0 0 0)) (1 (0 1e-4 0)))/" "$d/0/block/D"
(cd "$d" && formFoam > log.formFoam.elastic 2>&1) \
    || fail "stretch 1e-4 (see $d/log.formFoam.elastic)"
checkEffect "stretch 1e-4: effect report" "$d" plasticity plasticDissipation negligible
[ "$(effectValue "$d" plasticity plasticDissipation)" = 0 ] \
    && grep -q "^plasticity plasticDissipation .*the run stayed elastic" "$d/postProcessing/effects" \
    && pass "stretch 1e-4: the run stayed elastic (no dissipation)" \
    || fail "stretch 1e-4: plastic dissipation '$(effectValue "$d" plasticity plasticDissipation)', the report does not say the run stayed elastic"
[ -n "${KEEP:-}" ] && echo "    kept $d" || rm -rf "$d"
