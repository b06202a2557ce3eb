#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The ALE Navier-Stokes fluid on its own (fluidModel ALENavierStokes, no
# solid region), against exact solutions:
#   - plane Poiseuille flow (channel, developing from a uniform inflow at
#     Re = 10): outlet profile, pressure gradient 12 mu U/h^2, mass balance,
#     second order in the mesh; the Newton matrix against finite
#     differences (formFoam -checkTangent) and Newton's order, for linear
#     and upwind convection;
#   - a time-dependent inlet (OpenFOAM's uniformFixedValue: Turek & Hron's
#     cosine ramp times the parabola): the inflow at every step's time;
#   - Hagen-Poiseuille flow in a pipe (wedge mesh): profile and flow rate
#     pi R^4 dp/(8 mu L), second order;
#   - radial outflow u_r = c/r (wedge mesh): the hoop terms p/r and
#     -mu u_r/r^2 make u = c/r exact with the Bernoulli pressure;
#   - space conservation: a uniform flow through a box whose interior
#     points oscillate stays uniform to round-off (transient and steady);
#   - a motion that would invert cells stops with a message;
#   - bad input: clear errors naming the file and entry.
#------------------------------------------------------------------------------
cd "$(dirname "$0")" || exit 1
. ./testFunctions
here=$(pwd)
check="python3 $here/fluidCheck.py"

# runFluid <case dir in tests/cases> <copy> [edits...]: copy, mesh, run
runFluid() { runCopy "$1" "$2" water "${@:3}"; }

# orderShortfall <q> <error h> <error h/2>: q minus the observed order
orderShortfall()
{
    calc 'q - log(a/b)/log(2)' q="$1" a="$2" b="$3"
}

work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamFluid.XXXXXX")

#- Channel: coarse (with the tangent check) and fine
FORMFOAM_ARGS=-checkTangent runFluid poiseuilleChannel "$work/ch1"
FORMFOAM_ARGS= runFluid poiseuilleChannel "$work/ch2" \
    "sed -i 's/^nx .*/nx 100;/; s/^ny .*/ny 20;/' system/water/blockMeshDict"
for c in ch1 ch2; do
    grep -q '^End' "$work/$c/log.formFoam" && pass "channel $c: ran" \
        || { fail "channel $c: formFoam failed"; tail -20 "$work/$c/log.formFoam"; }
done
te=$(tangentError "$work/ch1/log.formFoam")
checkBelow "channel: Newton matrix vs finite differences (linear convection)" "$te" 1e-6
q=$(residualOrder "$work/ch1/log.formFoam")
checkBelow "channel: Newton order (> 1.8) [2 - q < 0.2]" \
    "$(calc '2 - q' q="$q")" 0.2
for c in ch1 ch2; do
    qin=$(summaryValue "$work/$c" inletFlowRate)
    qout=$(summaryValue "$work/$c" outletFlowRate)
    # (the inflow itself is imposed: flowRateInletVelocity 0.1 through a
    # 0.1 deep inlet; the outflow is computed)
    checkClose "channel $c: outflow = the inflow the inlet was given, 1 per unit depth" "$qout" 1 1e-10
    checkBelow "channel $c: mass balance |Q_in + Q_out|" \
        "$(calc 'abs(a + b)' a="$qin" b="$qout")" 1e-10
done
e1=$($check channel "$work/ch1" 1 50 10 10 1 1 9)
e2=$($check channel "$work/ch2" 1 100 20 10 1 1 9)
checkBelow "channel: outlet profile vs 6 U y(h-y)/h^2, 10 cells across (rel. to u_max)" "$e1" 0.015
checkBelow "channel: outlet profile, 20 cells across" "$e2" 0.004
checkBelow "channel: profile error second order [2 - log2(e10/e20) < 0.2]" \
    "$(orderShortfall 2 "$e1" "$e2")" 0.2
g=$(calc '(a - b)/4' a="$(summaryValue "$work/ch2" pressureAt4)" b="$(summaryValue "$work/ch2" pressureAt8)")
checkClose "channel: developed pressure gradient vs 12 mu U/h^2 = 1.2" "$g" 1.2 0.01

# The case edit that puts the ramped parabolic inlet (tests/cases/rampedInlet)
# into the channel's 0/water/U
rampInlet="python3 -c \"import re; p='0/water/U'; s=open(p).read(); s=re.sub(r'    inlet\\n    \\{[^}]*\\}', open('$here/rampedInlet').read().rstrip(), s); open(p,'w').write(s)\""

#- A time-dependent inlet through OpenFOAM's own conditions: the parabolic
#  profile u = 6 U y (h - y)/h^2 (mean U = 1, h = 1) ramped by Turek &
#  Hron's 0.5 (1 - cos(pi t/2)) for t < 2 (uniformFixedValue: a scale
#  Function1 of time with halfCosineRamp, the parabola as scale2 of y; the
#  unsteady FSI benchmarks' inflow), transient (Euler): every step takes
#  the inlet at its own time, so the inflow at t is the ramp times the
#  full one (the inlet's midpoint sum of the parabola: 1 + h_y^2/2)
FORMFOAM_ARGS= runFluid poiseuilleChannel "$work/ramp" \
    "sed -i 's/^ddtSchemes .*/ddtSchemes      { default Euler; }/' system/water/fvSchemes" \
    "sed -i 's/^endTime .*/endTime         3;/; s/^deltaT .*/deltaT          0.25;/' system/controlDict" \
    "sed -i 's/^\\( *centreVelocity .*\\)\$/\\1\\n    inflowAt05 { type fluidFlowRate; patch inlet; time 0.5; }\\n    inflowAt1 { type fluidFlowRate; patch inlet; time 1; }\\n    inflowAt3 { type fluidFlowRate; patch inlet; time 3; }/' system/solidSolution" \
    "$rampInlet"
if grep -q '^End' "$work/ramp/log.formFoam"; then
    pass "ramped inlet: ran (12 transient steps)"
    q3=$(summaryValue "$work/ramp" inflowAt3)
    checkClose "ramped inlet: full inflow at t = 3 (midpoint sum of the parabola over 10 faces: -1.005)" \
        "$q3" -1.005 1e-9
    checkClose "ramped inlet: inflow at t = 0.5 / full = 0.5 (1 - cos(pi/4))" \
        "$(calc 'a/b' a="$(summaryValue "$work/ramp" inflowAt05)" b="$q3")" \
        "$(calc '0.5*(1 - cos(atan2(0, -1)/4))')" 1e-9
    checkClose "ramped inlet: inflow at t = 1 / full = 0.5" \
        "$(calc 'a/b' a="$(summaryValue "$work/ramp" inflowAt1)" b="$q3")" 0.5 1e-9
else
    fail "ramped inlet: formFoam failed"; tail -20 "$work/ramp/log.formFoam"
fi

#- Time order: the ramped channel to t = 1 (the flow accelerating) with
#  dt = 0.05, 0.025, 0.0125; the pressure at x = 4 carries the inertia of
#  the flow ahead of it. Self-convergence: Euler first order, backward
#  (BDF2) second order
declare -A order
for scheme in Euler backward; do
    for n in 20 40 80; do
        FORMFOAM_ARGS= runFluid poiseuilleChannel "$work/ord$scheme$n" \
            "sed -i 's/^ddtSchemes .*/ddtSchemes      { default $scheme; }/' system/water/fvSchemes" \
            "sed -i 's/^deltaT .*/deltaT          $(calc '1/n' n=$n);/' system/controlDict" \
            "$rampInlet"
    done
    p1=$(summaryValue "$work/ord${scheme}20" pressureAt4)
    p2=$(summaryValue "$work/ord${scheme}40" pressureAt4)
    p3=$(summaryValue "$work/ord${scheme}80" pressureAt4)
    q=$(calc 'log((a - b)/(b - c))/log(2)' a="$p1" b="$p2" c="$p3")
    echo "time order, $scheme: p(x = 4, t = 1) = $p1, $p2, $p3: order $q"
    order[$scheme]=$q
done
# (Euler's observed order approaches 1 from above: 1.39 at these steps,
# 1.55 at twice them)
checkBetween "time order: Euler is first order (pre-asymptotic)" "${order[Euler]}" 0.9 1.6
checkBetween "time order: backward (BDF2) is second order" "${order[backward]}" 1.85 2.3

#- Upwind convection: not differentiable where a face flux changes sign
#  (v = 0 in a developed channel), so the channel converges, more slowly;
#  the Newton matrix is exact wherever the fluxes keep their signs: an
#  oblique uniform flow (in through the left and bottom, out through the
#  right and top) through the oscillating box, which must also stay uniform
FORMFOAM_ARGS= runFluid poiseuilleChannel "$work/chUp" \
    "sed -i 's/div(phi,U) Gauss linear;/div(phi,U) Gauss upwind;/' system/water/fvSchemes"
grep -q '^End' "$work/chUp/log.formFoam" && grep -q 'convection upwind' "$work/chUp/log.formFoam" \
    && pass "channel, upwind: converges, and the scene reports the scheme of fvSchemes" \
    || fail "channel, upwind: failed or scheme not reported"
e=$($check channel "$work/chUp" 1 50 10 10 1 1 9)
checkBelow "channel, upwind: outlet profile (developed: convection plays no part)" "$e" 0.015
FORMFOAM_ARGS=-checkTangent runFluid spaceConservation "$work/obl" \
    "sed -i 's/div(phi,U) Gauss linear;/div(phi,U) Gauss upwind;/' system/water/fvSchemes" \
    "sed -i 's/amplitude   (0.12 0.1 0);/amplitude   (0.05 0.04 0);/' constant/water/fluidProperties" \
    "sed -i 's/^    walls .*/    bottom { type patch; faces ((0 1 5 4)); }\\n    top { type patch; faces ((3 7 6 2)); }/' system/water/blockMeshDict" \
    "sed -i 's/uniform (1 0 0)/uniform (1 0.5 0)/g; s/^    walls .*/    bottom { type fixedValue; value uniform (1 0.5 0); }\\n    top { type zeroGradient; }/' 0/water/U" \
    "sed -i 's/^    walls .*/    bottom { type zeroGradient; }\\n    top { type fixedValue; value uniform 0; }/' 0/water/p"
te=$(tangentError "$work/obl/log.formFoam")
checkBelow "oblique flow, upwind: Newton matrix vs finite differences on the moving mesh" "$te" 1e-6
read -r du dp n <<< "$($check uniform "$work/obl" 1 0.5)"
checkBelow "oblique flow, upwind: uniform flow stays uniform, max |U - U0| over $n times" "$du" 1e-10
checkBelow "oblique flow, upwind: pressure stays zero, max |p|" "$dp" 1e-10

#- Pipe (wedge): flow rate and profile on two meshes
FORMFOAM_ARGS=-checkTangent runFluid poiseuillePipe "$work/pp1"
FORMFOAM_ARGS= runFluid poiseuillePipe "$work/pp2" \
    "sed -i 's/^nr .*/nr 20;/' system/water/blockMeshDict"
te=$(tangentError "$work/pp1/log.formFoam")
checkBelow "pipe: Newton matrix vs finite differences (wedge)" "$te" 1e-6
qExact=$(awk 'BEGIN { printf "%.15g", atan2(0, -1)*0.5^4*32/(8*0.1*10) }')
q1=$(summaryValue "$work/pp1" outletFlowRate)
q2=$(summaryValue "$work/pp2" outletFlowRate)
# (the planar faces of a 5 degree wedge make the cross-section a polygon:
# an O(angle^2) geometric error of about 0.2 % that no radial refinement
# removes)
checkClose "pipe: flow rate vs Hagen-Poiseuille pi R^4 dp/(8 mu L), 10 cells across R" "$q1" "$qExact" 0.003
checkClose "pipe: flow rate, 20 cells" "$q2" "$qExact" 0.003
e1=$($check pipe "$work/pp1" 1 50 10 10 0.5 32 0.1)
e2=$($check pipe "$work/pp2" 1 50 20 10 0.5 32 0.1)
checkBelow "pipe: profile vs dp/(4 mu L) (R^2 - r^2), 10 cells (rel. to the axis velocity)" "$e1" 0.01
# The largest error sits in the axis cell: on a wedge the cell centroids
# (2/3 of the first cell's radius, then the annuli's centroids) are not
# midway between the faces, so the face gradient there is first order
# (as in OpenFOAM's own wedge discretisation); away from the axis the
# error is second order
checkBelow "pipe: profile, 20 cells" "$e2" 0.0035
checkBelow "pipe: profile error decreases at least at order 0.6 (axis cell) [0.6 - log2(e10/e20) < 0]" \
    "$(orderShortfall 0.6 "$e1" "$e2")" 0
g=$(calc '(a - b)/4' a="$(summaryValue "$work/pp1" pressureAt4)" b="$(summaryValue "$work/pp1" pressureAt8)")
checkClose "pipe: pressure gradient dp/L = 3.2" "$g" 3.2 1e-6

#- Radial outflow (wedge): hoop terms
FORMFOAM_ARGS=-checkTangent runFluid radialFlow "$work/rf1"
FORMFOAM_ARGS= runFluid radialFlow "$work/rf2" \
    "sed -i 's/^nr .*/nr 48;/' system/water/blockMeshDict"
te=$(tangentError "$work/rf1/log.formFoam")
checkBelow "radial flow: Newton matrix vs finite differences" "$te" 1e-6
read -r p1 u1 <<< "$($check radial "$work/rf1" 1 24 0.5 2 1 1)"
read -r p2 u2 <<< "$($check radial "$work/rf2" 1 48 0.5 2 1 1)"
checkBelow "radial flow: p(r) - p(r_mid) vs rho c^2/2 (1/r_mid^2 - 1/r^2), 24 cells (rel. to the range)" "$p1" 0.01
checkBelow "radial flow: u_r vs c/r, 24 cells (rel. to c/r1)" "$u1" 0.005
checkBelow "radial flow: pressure error second order [2 - log2(e24/e48) < 0.3]" \
    "$(orderShortfall 2 "$p1" "$p2")" 0.3
# (observed 1.5e-7 at full precision; the check used to read both sides at
# 6 digits and claim 1e-9: issue 19)
qr=$(summaryValue "$work/rf1" outletFlowRate)
checkClose "radial flow: outflow of the full ring 2 pi r1 H u(r1) = pi (the wedge's chords scaled to the ring)" "$qr" \
    "$(awk 'BEGIN { printf "%.15g", atan2(0, -1) }')" 5e-7

#- Space conservation: transient (Euler, backward) and steady on the
#  oscillating mesh
FORMFOAM_ARGS=-checkTangent runFluid spaceConservation "$work/sc1"
FORMFOAM_ARGS= runFluid spaceConservation "$work/sc2" \
    "sed -i 's/default Euler;/default steadyState;/' system/water/fvSchemes"
FORMFOAM_ARGS=-checkTangent runFluid spaceConservation "$work/sc3" \
    "sed -i 's/default Euler;/default backward;/' system/water/fvSchemes"
for c in sc1 sc2 sc3; do
    read -r du dp n <<< "$($check uniform "$work/$c" 1 0)"
    checkBelow "space conservation $c: uniform flow stays uniform, max |U - U0| over $n times" "$du" 1e-10
    checkBelow "space conservation $c: pressure stays zero, max |p|" "$dp" 1e-10
done
moved=$($check moved "$work/sc1" 0.25)
checkBelow "space conservation: the mesh moved (largest point displacement at t = 0.25 > 0.1) [0.1 - d < 0]" \
    "$(calc '0.1 - d' d="$moved")" 0
vmin=$(sed -n 's/.*min V\/V_start \([^,]*\),.*/\1/p' "$work/sc1/log.formFoam" | sort -g | head -1)
checkBelow "space conservation: cell volumes changed (min V/V_start < 0.95)" "$vmin" 0.95
te=$(tangentError "$work/sc1/log.formFoam")
checkBelow "space conservation: Newton matrix vs finite differences on the moving mesh (transient)" "$te" 1e-6
te=$(tangentError "$work/sc3/log.formFoam")
checkBelow "space conservation: Newton matrix vs finite differences on the moving mesh (backward)" "$te" 1e-6

#- A motion that would invert cells: the step fails and the run stops
FORMFOAM_ARGS= runFluid spaceConservation "$work/inv" \
    "sed -i 's/amplitude   (0.12 0.1 0);/amplitude   (0.5 0.4 0);/' constant/water/fluidProperties"
rc=$?
expectFailure "mesh motion about to invert cells" $rc "$work/inv/log.formFoam" \
    "face [0-9]+ at .* degrees non-orthogonal, beyond maxNonOrthogonality 80 \(constant/water/fluidProperties\): the mesh motion is about to invert cells"
ls -d "$work"/inv/0.1* > /dev/null 2>&1 \
    && pass "mesh motion about to invert cells: the last converged state is written" \
    || fail "mesh motion about to invert cells: no state written"

#- Bad input
base="$here/poiseuilleChannel"
fp=constant/water/fluidProperties
mesh="blockMesh -region water > /dev/null 2>&1"
tryCase "fluid: no mesh" \
    "Fluid region 'water' .* has no mesh: .?constant/water/polyMesh.? is missing; run blockMesh -region water" \
    "true"
tryCase "fluid: unsupported velocity condition" \
    "Patch 'outlet' in 0/water/U: velocity condition type 'inletOutlet' is not available" \
    "$mesh; sed -i 's/outlet       { type zeroGradient; }/outlet { type inletOutlet; inletValue uniform (0 0 0); value uniform (0 0 0); }/' 0/water/U"
tryCase "fluid: outlet without a fixed pressure" \
    "Patch 'outlet': U is zeroGradient in 0/water/U but p in 0/water/p does not fix its value" \
    "$mesh; sed -i 's/outlet       { type fixedValue; value uniform 0; }/outlet { type zeroGradient; }/' 0/water/p"
tryCase "fluid: incompressible, pressure level undetermined" \
    "incompressible with no patch of fixed pressure in .?0/water/p.?" \
    "$mesh; sed -i 's/outlet       { type fixedValue; value uniform 0; }/outlet { type zeroGradient; }/; ' 0/water/p; sed -i 's/outlet       { type zeroGradient; }/outlet { type noSlip; }/' 0/water/U"
tryCase "fluid: non-positive viscosity" \
    "Entry 'mu' in .?constant/water/fluidProperties.? must be positive, got -0.1" \
    "$mesh; sed -i 's/^mu .*/mu -0.1;/' $fp"
tryCase "fluid: non-positive bulk modulus" \
    "Entry 'bulkModulus' in .?constant/water/fluidProperties.? must be a positive number or 'incompressible'" \
    "$mesh; sed -i 's/^bulkModulus .*/bulkModulus 0;/' $fp"
tryCase "fluid: mistyped entry" \
    "Unknown entry 'rhoo' in dictionary .*fluidProperties" \
    "$mesh; sed -i 's/^rho /rhoo /' $fp"
tryCase "fluid: convection scheme without an exact Newton matrix" \
    "div\(phi,U\) in system/water/fvSchemes: the ALE fluid's Newton matrix is exact for 'Gauss linear' and 'Gauss upwind'" \
    "$mesh; sed -i 's/div(phi,U) Gauss linear;/div(phi,U) Gauss limitedLinear 1;/' system/water/fvSchemes"
tryCase "fluid: unknown mesh motion" \
    "Entry 'meshMotion/type' in .?constant/water/fluidProperties.?: unknown 'wobbly'" \
    "$mesh; echo 'meshMotion { type wobbly; }' >> $fp"
tryCase "fluid alone: a mesh-motion diffusivity without a solid" \
    "Entry 'meshMotion/diffusivity' in .?constant/water/fluidProperties.?: the diffusivity belongs to the motion of a mesh that follows a solid; fluid region 'water' has none" \
    "$mesh; echo 'meshMotion { diffusivity inverseDistance; }' >> $fp"
tryCase "fluid alone: dynamic analysis needs a solid" \
    "dynamic analysis integrates a solid's inertia, and the scene has no solid region" \
    "$mesh; sed -i 's/^analysis .*/analysis dynamic;/' system/solidSolution"
tryCase "fluid alone: a solid summary type" \
    "type 'displacement' needs a solid region, and the scene has none" \
    "$mesh; sed -i 's/^{/{\n    tip { type displacement; point (0 0 0); component x; }/' system/solidSolution"
tryCase "fluid: summary point outside the fluid" \
    "Entry 'point' in .*: \(40 0.5 0.05\) is not inside the mesh of fluid region 'water'" \
    "$mesh; sed -i 's/point (8 0.5 0.05)/point (40 0.5 0.05)/' system/solidSolution"

rm -rf "$work"
