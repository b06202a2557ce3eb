#!/usr/bin/env bash
# Turek & Hron (2006) FSI2, tutorials/turekHronFSI2, reduced for the
# suite: the coarse meshes (fluid refinement 1: 4188 cells; flag 20 x 2
# Q9) restarted at t = 13 s from the state their full run wrote there
# (turekHronFSI2Coarse/13.tar.gz: the flag swinging periodically, its tip
# 80 mm up and down; provenance in turekHronFSI2Coarse/README), run for
# 1 s (two periods of the swing and the lift, four of the drag):
#   - the restart follows the full run: tip, drag and lift of every step
#     against the full run's history (turekHronFSI2Coarse/history.ref) to
#     1e-6 of their amplitudes;
#   - the mesh motion stiffened near the flag (meshMotion diffusivity
#     inverseDistance) keeps the fluid mesh valid at the full swing: the
#     largest face non-orthogonality stays below 60 deg (the uniform
#     diffusivity folded a cell at the tip, 80 deg, at uy = 52 mm);
#   - the summary's statistics over 13-14 s against the full run's over
#     13-15 s (the periodic state: 1 % in amplitudes, means and
#     frequencies);
#   - and against the benchmark: the coarse meshes' errors (the README's
#     table) within bounds a little wider than observed;
#   - kept factorisations: fewer than a third of the Newton iterations
#     (observed 0.11).
. "$(dirname "$0")/testFunctions"
. "$(dirname "$0")/turekHronUnsteady"
ref=$formFoamTop/tests/cases/turekHronFSI2Coarse

restartCoarse "FSI2 coarse" turekHronFSI2 "$ref" 13 14 "13 14"
followsFullRun "FSI2 coarse" "$ref" 13 190 1e-6
angle=$(sed -n 's/.*max non-orthogonality \([0-9.eE+-]*\) deg.*/\1/p' "$log" | sort -g | tail -1)
checkBelow "FSI2 coarse: the largest face non-orthogonality of the moving fluid mesh (deg)" \
    "$angle" 60
sameStatistics "FSI2 coarse (over 13-14 s; the full run over 13-15 s)" "$ref" 0.01 \
    uyAmplitude uyFrequency uxMean uxAmplitude uxFrequency dragMean dragAmplitude \
    liftAmplitude liftFrequency

# Against the benchmark (BENCHMARKS.md): uy 1.23 +- 80.6 mm [2.0 Hz], ux
# -14.58 +- 12.44 mm [3.8 Hz], drag 208.83 +- 73.75, lift 0.88 +- 234.2
# (coarse meshes, the full run over 13-15 s: uy 1.30 +- 77.22 mm [1.943
# Hz], ux -13.20 +- 11.50 mm [3.883 Hz], drag 207.10 +- 67.69, lift 0.63 +-
# 234.35: the swing 4 % short, the frequencies within 3 %; README's table). The bounds sit a
# little outside the observed values: a change that moves them is a
# change of the physics
checkBetween "FSI2 coarse: uy frequency / 2.0 Hz" "$(ratioTo uyFrequency 2.0)" 0.96 0.98
checkBetween "FSI2 coarse: lift frequency / 2.0 Hz" "$(ratioTo liftFrequency 2.0)" 0.96 0.98
checkBetween "FSI2 coarse: ux frequency / 3.8 Hz" "$(ratioTo uxFrequency 3.8)" 1.01 1.03
checkBetween "FSI2 coarse: uy amplitude / 80.6 mm" "$(ratioTo uyAmplitude 0.0806)" 0.94 0.975
checkBetween "FSI2 coarse: ux mean / -14.58 mm" "$(ratioTo uxMean -0.01458)" 0.88 0.93
checkBetween "FSI2 coarse: lift amplitude / 234.2" "$(ratioTo liftAmplitude 234.2)" 0.98 1.02
checkBetween "FSI2 coarse: drag mean / 208.83" "$(ratioTo dragMean 208.83)" 0.98 1.0

keptFactorisations "FSI2 coarse" 0.3

rm -rf "$c"
