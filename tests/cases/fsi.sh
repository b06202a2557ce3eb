#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The monolithic fluid-structure coupling (interface block) on the piston
# problem (tests/cases/piston): oil injected at the bottom of a 1 x 1
# column lifts an elastic plug (neo-Hookean, plane strain, rollers on the
# sides, top fixed) that closes it; the fluid has 2 cells across, the plug
# one element (non-matching interface).
#
# Analytic response: the plug is in uniaxial strain, stretch l = 1 - d
# (d: its lift, thickness 1), Cauchy stress
#     sigma_yy = [G (2/3) l^(-2/3) (l^2 - 1) + kappa ln l]/l = -p,
# and the oil's mass is the initial plus the injected at the reference
# density, rho0 (1 + V_inj) = rho0 exp(p/K) (1 + d).
# Checks:
#   - the incompressible limit: lift = injected volume (no fixed-pressure
#     patch needed: the plug sets the pressure);
#   - ALENavierStokes and hydrostatic against it (the ALE fluid's pressure
#     is uniform to its dynamic pressure, rho u^2 ~ 1e-5 here);
#   - the Newton matrix of the fluid and its coupling with the solid
#     (interface velocities, forces, the mesh that follows the solid)
#     against central differences (formFoam -checkTangent), and Newton's
#     quadratic rate, static and dynamic (trapezoidal rule: the kinematic
#     condition uses the integrator's velocity);
#   - a restart from the middle reproduces the continuous run;
#   - kept tangents (newton modified) reach the same states with fewer
#     factorisations;
#   - bad input: clear errors naming the file and entry.
#------------------------------------------------------------------------------
cd "$(dirname "$0")" || exit 1
. ./testFunctions
here=$(pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamFsi.XXXXXX")

# runPiston <copy> [edits...]: copy the piston, mesh, run formFoam
# $FORMFOAM_ARGS
runPiston() { runCopy piston "$1" "oil plug" "${@:2}"; }

# The analytic lift and pressure at the end (V_inj = 0.1)
read -r dExact pExact < <(python3 - <<'PY'
import math
E, nu, K, dV = 100.0, 0.3, 50.0, 0.1
G = E/(2*(1 + nu)); kappa = E/(3*(1 - 2*nu))
def p(d):
    l = 1 - d
    return -(G*2/3*l**(-2/3)*(l*l - 1) + kappa*math.log(l))/l
f = lambda d: (1 + d) - (1 + dV)*math.exp(-p(d)/K)
a, b = 0.0, 0.5
for _ in range(200):
    m = 0.5*(a + b)
    if f(a)*f(m) <= 0: b = m
    else: a = m
print("%.10g %.10g" % (a, p(a)))
PY
)
echo "analytic: lift $dExact, pressure $pExact"

#- ALE, static, with the tangent check
FORMFOAM_ARGS=-checkTangent runPiston "$work/ale"
log=$work/ale/log.formFoam
if grep -q '^End' "$log"; then
    pass "piston ALE: ran"
    checkClose "piston ALE: plug lift" "$(summaryValue "$work/ale" plugLift)" "$dExact" 1e-4
    checkClose "piston ALE: oil pressure" "$(summaryValue "$work/ale" pressure)" "$pExact" 1e-4
    checkBelow "piston ALE: coupled Newton matrix vs finite differences" \
        "$(tangentError "$log")" 1e-7
    grep -q "coupling with [0-9]* solid dofs" "$log" \
        && pass "piston ALE: the check covers the coupling with the solid" \
        || fail "piston ALE: the tangent check did not reach the solid's dofs"
    q=$(residualOrder "$log")
    checkBelow "piston ALE: Newton order $q (2 - q)" "$(calc '2 - q' q="$q")" 0.3
    # The mesh followed the plug: the oil's volume is 1 + lift
    V=$(sed -n 's/.* V = \([^;]*\);.*/\1/p' "$log" | tail -1)
    checkClose "piston ALE: oil volume = 1 + lift" "$V" \
        "$(calc '1 + d' d="$dExact")" 1e-6
else
    fail "piston ALE: formFoam failed"; tail -20 "$log"
fi

#- A restart from the middle (the oil's fields and moved mesh, the plug's
#  state) reproduces the continuous run
FORMFOAM_ARGS= runPiston "$work/rst" \
    "sed -i 's/^writeInterval .*/writeInterval 0.5;/; s/^endTime .*/endTime 0.5;/' system/controlDict"
(
    cd "$work/rst" || exit 1
    sed -i 's/^endTime .*/endTime 1;/; s/^startFrom .*/startFrom latestTime;/' system/controlDict
    timeout 300 formFoam > log.restart 2>&1
)
if grep -q '^End' "$work/rst/log.restart"; then
    checkClose "piston ALE: restart at t = 0.5 reproduces the lift" \
        "$(summaryValue "$work/rst" plugLift)" "$(summaryValue "$work/ale" plugLift)" 1e-7
    checkClose "piston ALE: restart at t = 0.5 reproduces the pressure" \
        "$(summaryValue "$work/rst" pressure)" "$(summaryValue "$work/ale" pressure)" 1e-7
else
    fail "piston ALE: restart failed"; tail -20 "$work/rst/log.restart"
fi

#- The hydrostatic model from the same case (the one-word switch)
FORMFOAM_ARGS= runPiston "$work/hyd" \
    "sed -i 's/^fluidModel .*/fluidModel hydrostatic;/' constant/oil/fluidProperties"
if grep -q '^End' "$work/hyd/log.formFoam"; then
    checkClose "piston hydrostatic: plug lift" "$(summaryValue "$work/hyd" plugLift)" "$dExact" 1e-5
    checkClose "piston hydrostatic: pressure" "$(summaryValue "$work/hyd" pressure)" "$pExact" 1e-5
    checkClose "piston: ALE vs hydrostatic lift" "$(summaryValue "$work/ale" plugLift)" \
        "$(summaryValue "$work/hyd" plugLift)" 1e-4
else
    fail "piston hydrostatic: formFoam failed"; tail -20 "$work/hyd/log.formFoam"
fi

#- Incompressible oil: the plug's compliance alone sets the pressure; the
#  lift is the injected volume, 0.1, and p = -sigma_yy(l = 0.9)
pInc=$(python3 -c "
import math
E, nu = 100.0, 0.3; G = E/(2*(1 + nu)); k = E/(3*(1 - 2*nu)); l = 0.9
print(-(G*2/3*l**(-2/3)*(l*l - 1) + k*math.log(l))/l)")
FORMFOAM_ARGS= runPiston "$work/inc" \
    "sed -i 's/^bulkModulus .*/bulkModulus incompressible;/' constant/oil/fluidProperties"
if grep -q '^End' "$work/inc/log.formFoam"; then
    checkClose "piston, incompressible oil: lift = injected volume" \
        "$(summaryValue "$work/inc" plugLift)" 0.1 1e-5
    checkClose "piston, incompressible oil: pressure" \
        "$(summaryValue "$work/inc" pressure)" "$pInc" 1e-4
else
    fail "piston incompressible: formFoam failed"; tail -20 "$work/inc/log.formFoam"
fi

#- Finer, non-matching the other way: 3 fluid faces on 2 solid edges (a
#  face spans two edges), 2 x 12 cells
FORMFOAM_ARGS= runPiston "$work/fine" \
    "sed -i 's/^nx .*/nx 3;/; s/^ny .*/ny 12;/' system/oil/blockMeshDict" \
    "sed -i 's/(1 \$ny 1)/(2 \$ny 1)/' system/plug/blockMeshDict"
if grep -q '^End' "$work/fine/log.formFoam"; then
    checkClose "piston, 3 faces on 2 edges: plug lift" \
        "$(summaryValue "$work/fine" plugLift)" "$dExact" 2e-3
else
    fail "piston fine: formFoam failed"; tail -20 "$work/fine/log.formFoam"
fi

# dynamicEdits <ddt scheme>: the case edits (array dyn) of the dynamic
# piston: the plug with mass under the trapezoidal rule, steps of 0.05,
# the oil's ddt scheme
dynamicEdits()
{
    dyn=(
        "sed -i 's/^analysis .*/analysis dynamic;\nintegrator trapezoidal;\nmass consistent;/' system/solidSolution"
        "sed -i 's/E 100; nu 0.3;/E 100; nu 0.3; rho 1;/' constant/plug/solidProperties"
        "sed -i 's/default steadyState;/default $1;/' system/oil/fvSchemes"
        "sed -i 's/^deltaT .*/deltaT 0.05;/' system/controlDict"
    )
}

#- Dynamic: trapezoidal rule for the plug, Euler for the oil
dynamicEdits Euler
FORMFOAM_ARGS=-checkTangent runPiston "$work/dyn" "${dyn[@]}"
log=$work/dyn/log.formFoam
if grep -q '^End' "$log"; then
    pass "piston dynamic: ran"
    checkBelow "piston dynamic: coupled Newton matrix vs finite differences" \
        "$(tangentError "$log")" 1e-7
    q=$(residualOrder "$log")
    checkBelow "piston dynamic: Newton order $q (2 - q)" "$(calc '2 - q' q="$q")" 0.3
    # The plug oscillates about the static path (period about 0.5): at the
    # end within 10 % of the static lift
    checkClose "piston dynamic: lift near the static one" \
        "$(summaryValue "$work/dyn" plugLift)" "$dExact" 0.1
else
    fail "piston dynamic: formFoam failed"; tail -20 "$log"
fi

#- Dynamic with the oil's backward scheme (BDF2): the coupled Newton
#  matrix with the scheme's older level, and a restart from the middle
#  (the level before the restart time, backwardHistory, read back)
#  reproduces the continuous run
dynamicEdits backward
FORMFOAM_ARGS=-checkTangent runPiston "$work/bdf" "${dyn[@]}"
FORMFOAM_ARGS= runPiston "$work/bdfr" "${dyn[@]}" \
    "sed -i 's/^writeInterval .*/writeInterval 0.5;/; s/^endTime .*/endTime 0.5;/' system/controlDict"
(
    cd "$work/bdfr" || exit 1
    sed -i 's/^endTime .*/endTime 1;/; s/^startFrom .*/startFrom latestTime;/' system/controlDict
    timeout 300 formFoam > log.restart 2>&1
)
log=$work/bdf/log.formFoam
if grep -q '^End' "$log" && grep -q '^End' "$work/bdfr/log.restart"; then
    checkBelow "piston dynamic, backward oil: coupled Newton matrix vs finite differences" \
        "$(tangentError "$log")" 1e-7
    [ -f "$work/bdfr/0.5/oil/backwardHistory" ] \
        && pass "piston dynamic, backward oil: the level before is written with the fields" \
        || fail "piston dynamic, backward oil: no 0.5/oil/backwardHistory"
    checkClose "piston dynamic, backward oil: restart at t = 0.5 reproduces the lift" \
        "$(summaryValue "$work/bdfr" plugLift)" "$(summaryValue "$work/bdf" plugLift)" 1e-10
    checkClose "piston dynamic, backward oil: restart at t = 0.5 reproduces the pressure" \
        "$(summaryValue "$work/bdfr" pressure)" "$(summaryValue "$work/bdf" pressure)" 1e-10
else
    fail "piston dynamic, backward oil: formFoam failed"; tail -20 "$log" "$work/bdfr/log.restart"
fi

#- Dynamic with kept tangents (solidSolution newton modified): the same
#  states as full Newton (the dynamic run above) to its tolerance, with
#  fewer factorisations than iterations
dynamicEdits Euler
FORMFOAM_ARGS= runPiston "$work/kept" "${dyn[@]}" \
    "sed -i 's/^mass consistent;/&\nnewton modified;/' system/solidSolution"
log=$work/kept/log.formFoam
if grep -q '^End' "$log"; then
    checkClose "piston dynamic, kept tangent: lift = full Newton's" \
        "$(summaryValue "$work/kept" plugLift)" "$(summaryValue "$work/dyn" plugLift)" 1e-6
    its=$(sed -n 's/^ *steps [0-9]*, Newton iterations \([0-9]*\).*/\1/p' "$log")
    facs=$(sed -n 's/^ *factorisations *\([0-9]*\) (count).*/\1/p' "$log")
    echo "kept tangent: $facs factorisations for $its iterations"
    checkBelow "piston dynamic, kept tangent: factorisations per iteration" \
        "$(calc 'f/i' f="$facs" i="$its")" 0.5
else
    fail "piston dynamic, kept tangent: formFoam failed"; tail -20 "$log"
fi

#- The stiffened mesh motion (meshMotion diffusivity inverseDistance,
#  exponent 1.5): other interior points, the same plug (the oil's flow is
#  uniform across and linear along the column on any of its meshes), and
#  the Newton matrix's mesh rows with the distance-weighted Laplacian
FORMFOAM_ARGS=-checkTangent runPiston "$work/stiff" \
    "echo 'meshMotion { diffusivity inverseDistance; exponent 1.5; }' >> constant/oil/fluidProperties"
log=$work/stiff/log.formFoam
if grep -q '^End' "$log"; then
    grep -q "mesh motion: harmonic (diffusivity inverseDistance, exponent 1.5" "$log" \
        && pass "piston ALE, inverse-distance mesh motion: the log says which" \
        || fail "piston ALE, inverse-distance mesh motion: not in the log"
    checkClose "piston ALE, inverse-distance mesh motion: plug lift" \
        "$(summaryValue "$work/stiff" plugLift)" "$dExact" 1e-4
    checkBelow "piston ALE, inverse-distance mesh motion: coupled Newton matrix vs finite differences" \
        "$(tangentError "$log")" 1e-7
    # the interior points moved otherwise (the first cell row's top)
    p0=$(ls -d "$work/ale"/[1-9]* | sort -g | tail -1)/oil/polyMesh/points
    p1=$(ls -d "$work/stiff"/[1-9]* | sort -g | tail -1)/oil/polyMesh/points
    if [ -f "$p0" ] && [ -f "$p1" ]; then
        cmp -s "$p0" "$p1" && fail "piston ALE, inverse-distance mesh motion: the same points as the uniform one" \
            || pass "piston ALE, inverse-distance mesh motion: the interior points differ"
    else
        fail "piston ALE, inverse-distance mesh motion: no points written"
    fi
else
    fail "piston ALE, inverse-distance mesh motion: formFoam failed"; tail -20 "$log"
fi

#- Bad input
base=$work/base
FORMFOAM_ARGS= runPiston "$base"
rm -rf "$base"/[1-9]* "$base/postProcessing" "$base/log.formFoam"
tryCase "fluidInterface missing" \
    "Entry 'fluidInterface' missing or empty in constant/oil/fluidProperties.*interface with solid region 'plug'" \
    "sed -i '/^fluidInterface/d' constant/oil/fluidProperties"
tryCase "interface patch not movingWallVelocity" \
    "Patch 'top' in 0/oil/U: an interface patch .* must be movingWallVelocity, not noSlip" \
    "sed -i 's/top          { type movingWallVelocity; value uniform (0 0 0); }/top { type noSlip; }/' 0/oil/U"
tryCase "movingWallVelocity not on the interface" \
    "Patch 'sides' in 0/oil/U: movingWallVelocity is the condition of the interface" \
    "sed -i 's/sides        { type slip; }/sides { type movingWallVelocity; value uniform (0 0 0); }/' 0/oil/U"
tryCase "unknown fluid interface patch" \
    "Entry 'fluidInterface' in constant/oil/fluidProperties: 'lid' is not a patch of fluid region 'oil'" \
    "sed -i 's/^fluidInterface .*/fluidInterface (lid);/' constant/oil/fluidProperties"
tryCase "meshes do not share the interface" \
    "is [0-9.e-]* away from the solid's wetted patches.*the fluid and solid meshes must share the interface" \
    "sed -i 's/(0 1 0) (1 1 0) (1 2 0) (0 2 0)/(0 1.1 0) (1 1.1 0) (1 2 0) (0 2 0)/; s/(0 1 0.1) (1 1 0.1)/(0 1.1 0.1) (1 1.1 0.1)/' system/plug/blockMeshDict && blockMesh -region plug > /dev/null 2>&1"
tryCase "plane fluid, axisymmetric solid" \
    "Fluid region 'oil' .* and solid region 'plug' .*analysisType.*: the solid is axisymmetric but the fluid mesh has no wedge patches" \
    "sed -i 's/planeStrain/axisymmetric/' constant/plug/solidProperties;
     sed -i 's/components (x y)/components (r z)/; s/components *(x)/components (r)/' 0/plug/D;
     sed -i 's/component *y;/component z;/' system/solidSolution"
tryCase "pressure control with the ALE fluid" \
    "Entry 'pressure' in constant/oil/fluidProperties: pressure control is the hydrostatic model's" \
    "sed -i 's/^injectedVolume .*/pressure table ((0 0) (1 1));/; /^inlet /d' constant/oil/fluidProperties"
tryCase "injection without an inlet" \
    "injectedVolume and inlet go together" \
    "sed -i '/^inlet /d' constant/oil/fluidProperties"
tryCase "fixed pressure on the interface" \
    "Patch 'top' in 0/oil/p: the pressure on the interface with the solid is the fluid's own" \
    "sed -i 's/top          { type zeroGradient; }/top { type fixedValue; value uniform 0; }/' 0/oil/p"

tryCase "unknown mesh-motion diffusivity" \
    "Entry 'meshMotion/diffusivity' in constant/oil/fluidProperties: unknown 'quadratic'; valid: 2\(uniform inverseDistance\)" \
    "echo 'meshMotion { diffusivity quadratic; }' >> constant/oil/fluidProperties"
tryCase "mesh-motion exponent without inverseDistance" \
    "Entry 'meshMotion/exponent' in constant/oil/fluidProperties belongs to diffusivity inverseDistance" \
    "echo 'meshMotion { exponent 2; }' >> constant/oil/fluidProperties"
tryCase "mesh-motion exponent out of range" \
    "Entry 'meshMotion/exponent' in constant/oil/fluidProperties is out of range: -1" \
    "echo 'meshMotion { diffusivity inverseDistance; exponent -1; }' >> constant/oil/fluidProperties"
tryCase "mesh-motion diffusivity a dictionary" \
    "file: .*constant/oil/fluidProperties.meshMotion.diffusivity at line" \
    "echo 'meshMotion { diffusivity { type inverseDistance; } }' >> constant/oil/fluidProperties"

tryCase "unknown Newton method" \
    "Entry 'newton' in .*solidSolution.?: unknown 'quasi'; valid: full modified" \
    "sed -i 's/^analysis .*/&\nnewton quasi;/' system/solidSolution"
tryCase "kept-tangent contraction out of range" \
    "Entry 'keptTangentContraction' in .*solidSolution.? must be in \(0, 1\)" \
    "sed -i 's/^analysis .*/&\nnewton modified;\nkeptTangentContraction 1.5;/' system/solidSolution"
tryCase "kept-tangent contraction without modified Newton" \
    "Entry 'keptTangentContraction' in .*solidSolution.? needs newton modified" \
    "sed -i 's/^analysis .*/&\nkeptTangentContraction 0.5;/' system/solidSolution"

rm -rf "$work"
