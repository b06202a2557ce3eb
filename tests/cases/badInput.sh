#!/usr/bin/env bash
# Bad input must stop formFoam with a clear message naming file and entry.
. "$(dirname "$0")/testFunctions"

base=$(caseCopy cooksMembrane)
(cd "$base" && blockMesh -region solid > log.blockMesh 2>&1) \
    || fail "blockMesh on the base case"

# tryCase (testFunctions) runs broken copies of $base; afterTry checks that
# the input in the start time directory survives a failed run
afterTry()
{
    local label=$1 c=$2
    if ! diff -q "$base/0/solid/D" "$c/0/solid/D" >/dev/null \
       && [ "$label" = "inverted elements (huge load)" ]; then
        grep -q 'traction (0 1e3 0)' "$c/0/solid/D" \
            && pass "$label: 0/solid/D kept" || fail "$label: 0/solid/D overwritten"
    fi
}

props=constant/solid/solidProperties
tryCase "unknown element type" "Unknown element type 'Q9P2'|unknown element type 'Q9P2'.*Q9P3" \
    "foamDictionary -entry elementType -set Q9P2 $props >/dev/null"
tryCase "unknown material" "Unknown material type 'neoHooke'.*|valid.*neoHookean" \
    "foamDictionary -entry material/type -set neoHooke $props >/dev/null"
tryCase "negative Young's modulus" "'E'.*solidProperties|solidProperties.*'E'" \
    "foamDictionary -entry material/E -set -1 $props >/dev/null"
tryCase "Poisson ratio 0.5" "'nu'" \
    "foamDictionary -entry material/nu -set 0.5 $props >/dev/null"
tryCase "missing parameter" "nu.*not found|not found.*nu|Entry 'nu'" \
    "foamDictionary -entry material/nu -remove $props >/dev/null"
plastic="type elastoPlastic; hardening { type swift; K 1; eps0 0.01; n 0.2; }"
tryCase "plasticity: out-of-range hardening exponent" "Entry 'hardening/n'.*solidProperties.*out of range" \
    "sed -i 's/type        linearElastic;/${plastic/n 0.2/n -0.2}/' $props"
tryCase "plasticity: mistyped hardening entry" "unknown entry 'hardening/nn'" \
    "sed -i 's/type        linearElastic;/${plastic/n 0.2;/n 0.2; nn 2;}/' $props"
tryCase "plasticity: unknown hardening law" "unknown hardening/type 'swiftt'.*valid: perfect linear swift voce tabulated" \
    "sed -i 's/type        linearElastic;/${plastic/swift/swiftt}/' $props"
tryCase "plasticity: negative r-value" "Entry 'yield/r90'.*out of range" \
    "sed -i 's/type        linearElastic;/$plastic yield { type hill48; r0 1.5; r45 1.2; r90 -2; rollingDirection x; normalDirection y; }/' $props"
tryCase "mistyped entry" "Unknown entry 'elemntType'" \
    "sed -i 's/^elementType/elemntType/' $props"
tryCase "unknown analysisType" "analysisType.*planeStress|planeStress.*analysisType" \
    "foamDictionary -entry analysisType -set planeStress $props >/dev/null"
tryCase "unknown boundary condition" "Unknown boundary condition type 'fixed'" \
    "sed -i 's/left            { type fixedDisplacement; }/left { type fixed; }/' 0/solid/D"
tryCase "patch without condition" "No boundary condition for patch 'top'" \
    "sed -i '/^    top /d' 0/solid/D"
tryCase "unknown linear solver" "linearSolver.*mumps|mumps.*valid" \
    "foamDictionary -entry linearSolver -set mumps system/solidSolution >/dev/null"
tryCase "missing mesh" "polyMesh|points" \
    "rm -rf constant/solid/polyMesh"
tryCase "mesh that cannot be upgraded (3D)" "no 'empty' or 'wedge' patches" \
    "sed -i 's/type            empty;/type            patch;/' constant/solid/polyMesh/boundary"
tryCase "summary point outside the mesh" "outside the mesh" \
    "foamDictionary -entry summary/tipDisplacementY/point -set '(100 100 0)' system/solidSolution >/dev/null"
# an element turned inside out: the load is so large that det F <= 0 in
# every attempt; formFoam must stop with a message, not write garbage
tryCase "inverted elements (huge load)" "det F = .* <= 0.*|no convergence.*cutbacks" \
    "foamDictionary -entry material/type -set neoHookean $props >/dev/null;
     sed -i 's/traction (0 0.0625 0)/traction (0 1e3 0)/' 0/solid/D;
     foamDictionary -entry minDeltaT -set 0.01 system/solidSolution >/dev/null"
rm -rf "$base"
