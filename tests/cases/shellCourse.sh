#!/usr/bin/env bash
# The geometrically nonlinear part of the shell obstacle course through
# the case layer (issue 22; SHELLS.md):
#   1. Slit annular plate lifted by a line force (tutorials/shellBenchmarks/
#      slitAnnularPlate; Sze, Liu & Lo 2004): MITC4+ 10 x 80, a lineLoad
#      on the side of the sheet rising to 0.8 per unit length, 20 steps:
#      the lift of the loaded side at the inner and outer rim within 2 %
#      of Sze's 10.468, 13.768 at half load and 13.891, 17.528 at full
#      load (observed -0.9 to -1.3 %), and equal (1e-3) to the same mesh
#      solved through the model directly (shellBenchmarksTest.C: 13.7139,
#      17.3535 at full load).
. "$(dirname "$0")/testFunctions"

c=$(caseCopy shellBenchmarks/slitAnnularPlate)
(cd "$c" && blockMesh -region plate > log.blockMesh 2>&1 && formFoam > log.formFoam 2>&1) \
    || fail "slit annular plate run (see $c/log.formFoam)"
checkClose "slit plate: w_A at half load" "$(summaryValue "$c" wA50)" 10.468 0.02
checkClose "slit plate: w_B at half load" "$(summaryValue "$c" wB50)" 13.768 0.02
checkClose "slit plate: w_A at full load" "$(summaryValue "$c" wA)" 13.891 0.02
checkClose "slit plate: w_B at full load" "$(summaryValue "$c" wB)" 17.528 0.02
checkClose "slit plate: w_A as the model directly" "$(summaryValue "$c" wA)" 13.7139 1e-3
checkClose "slit plate: w_B as the model directly" "$(summaryValue "$c" wB)" 17.3535 1e-3
rm -rf "$c"
