#!/usr/bin/env bash
# Pure bending of an elastic-plastic plane-strain strip and springback
# (tutorials/pureBendingSpringback): the radius after release against the
# classical closed form (perfect plasticity) and against the numerical
# through-thickness integration (Swift hardening), BENCHMARKS.md; a restart
# from the bent state (material history from feHistory) must reproduce the
# continuous run.
. "$(dirname "$0")/testFunctions"

c=$(caseCopy pureBendingSpringback)
(cd "$c" && timeout 1800 ./Allrun -noVariants > log.Allrun 2>&1) || fail "pure bending run (see $c/log.formFoam)"
# Tolerances: observed +0.027 % (closed form) and -0.007 % (Swift); 0.1 %
# of the radius is 0.43 % of the springback curvature change 1/50 - 1/R
# (the old 1 % passed a 4-6 % error in it). The loaded radius is not
# checked: it is L over the end rotation, which the case prescribes.
R=$(summaryValue "$c" radiusAfterSpringback)
checkClose "perfect plasticity: radius after springback vs closed form" \
    "$R" "$(summaryValue "$c" radiusAnalytic)" 1e-3
checkBelow "Newton iterations per step" "$(summaryValue "$c" newtonIterationsPerStep)" 8

# Restart from the bent state at t = 1 (springback only)
r=$(mktemp -d "${TMPDIR:-/tmp}/formFoamRestart.XXXXXX")
cp -r "$c/." "$r/"
rm -rf "$r/2" "$r/postProcessing"
sed -i 's/^startTime .*/startTime       1;/' "$r/system/controlDict"
(cd "$r" && formFoam > log.restart 2>&1) || fail "restart run (see $r/log.restart)"
grep -q "Restarting from the state written at time 1" "$r/log.restart" \
    && pass "restart reads the state at t = 1" \
    || fail "restart did not read the state at t = 1"
checkClose "restart: radius after springback equals the continuous run" \
    "$(summaryValue "$r" radiusAfterSpringback)" "$R" 1e-6

# Swift hardening against the numerical integration
s="$c/swift"
(cd "$s" && timeout 1800 ./Allrun > log.Allrun 2>&1) || fail "Swift run (see $s/log.formFoam)"
checkClose "Swift: radius after springback vs through-thickness integration" \
    "$(summaryValue "$s" radiusAfterSpringback)" "$(summaryValue "$s" radiusAnalytic)" 5e-4
rm -rf "$c" "$r"
