#!/usr/bin/env bash
# The NUMISHEET'93 square cup, reduced (issue 23's CI case; the tutorial
# is to come): a quarter aluminium blank 75 x 75 x 0.81 (Hill'48), 20 x 20
# MITC4 shells with 5 points through the thickness, drawn to a punch
# stroke of 3.9 mm by rigid tools swept around a square core, the blank
# holder force-controlled (4.9 kN on the quarter) and resting on the
# blank at zero gap from the first step, Coulomb friction 0.162
# (tests/cases/squareCup). What it guards is numerical stability in 3D
# sheet forming: before 2026-11-27 this case stopped in its first step
# (the zero-gap holder started at the knee of the contact law; the
# pinched flange had no stiffness across its thickness; a friction frame
# failed on the tools' core), contactModel.H. Checks:
#   - the run reaches the stroke; its first step converges without a
#     cutback and the run takes at most 5 cutbacks (observed 0 and 2);
#   - the holder carries its force, 4900 within 1e-8 (force control);
#   - the tools' forces on the blank balance in z (no other load acts
#     across the symmetry planes) within 1e-6 of the die's force
#     (observed 1e-15);
#   - the flange edge draws in, more along the axis of symmetry than
#     along the diagonal (the square cup's known pattern: the diagonal's
#     flange is compressed the most);
#   - Newton converges quadratically at the end of the steps (observed
#     order, median over the steps, at least 1.8);
#   - the effect report: plasticity and friction matter (the shells'
#     plastic dissipation);
#   - summary type maxDisplacement: the flange edges' largest in-plane
#     displacement is at least the draw-in at the edge's point on the
#     axis (drawInX) and below twice it; the largest displacement since
#     t = 0.05 (the end of the first process step) is positive;
#   - a restart from the state written at mid-stroke (t = 0.05, that
#     step's end) reproduces the continuous run's punch force, draw-ins
#     and the displacement since t = 0.05 (which reads that state back
#     from its time directory after the restart) to 1e-10;
#   - formFoam -checkTangent: the Newton matrix agrees with central
#     differences of the residual along the Newton updates (median).
. "$(dirname "$0")/testFunctions"
work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamSquareCup.XXXXXX")
c=$work/cup
if runCopy squareCup "$c" blank && [ -f "$c/postProcessing/summary" ]; then
    v() { summaryValue "$c" "$1"; }
    if grep -q "^Step 1 .*(cutback" "$c/log.formFoam"; then
        fail "square cup: the first step (holder at zero gap) was cut back"
    else
        pass "square cup: the first step (holder at zero gap) converges without a cutback"
    fi
    checkBelow "square cup: cutbacks over the stroke" "$(v cutbacks)" 5.5
    checkClose "square cup: the holder carries its force" "$(calc '-f' f="$(v holderForceZ)")" 4900 1e-8
    checkBelow "square cup: z balance of the tools' forces / die force" \
        "$(calc 'abs(p + d + h)/abs(d)' p="$(v punchForceZ)" d="$(v dieForceZ)" h="$(v holderForceZ)")" 1e-6
    checkBetween "square cup: draw-in along the diagonal (mm)" "$(v drawInDiagonal)" 0 "$(v drawInX)"
    checkBelow "square cup: Newton order (median over the steps) above 1.8" 1.8 "$(newtonOrder "$c/log.formFoam")"
    checkBetween "square cup: the flange edges' largest in-plane displacement (maxDisplacement) between drawInX and twice it" \
        "$(v edgeDrawIn)" "$(v drawInX)" "$(calc '2*d' d="$(v drawInX)")"
    checkBetween "square cup: the largest displacement since t = 0.05 (maxDisplacement since)" \
        "$(v movedSince)" 1e-6 100
    # The effect report through the shells: the drawn flange flows
    # plastically (shellSet::plasticDissipation; observed 0.76 of the
    # internal work), friction dissipates (0.15 of the supplied work)
    checkEffect "square cup: effect report" "$c" plasticity plasticDissipation matters
    checkEffect "square cup: effect report" "$c" friction frictionDissipation matters
    # Restart from the written state in the middle of the stroke: the
    # rest of the run reproduces the continuous one (shell frames and
    # thickness, contact closest points, frames and multipliers, the
    # force-controlled holder, the predictor); 1e-7 before the commit
    # after a restart kept the contact state as read (contactModel.C)
    r=$work/restart
    cp -r "$c" "$r"
    tr=$(ls -d "$r"/0.0[1-9]* 2>/dev/null | head -1)
    if [ -n "$tr" ] && [ -d "$r/0.1" ]; then
        rm -rf "$r/0.1"
        sed -i 's/^startFrom .*/startFrom       latestTime;/' "$r/system/controlDict"
        if (cd "$r" && timeout 600 formFoam > log.restart 2>&1) \
           && grep -q "Restarting from the state written at time ${tr##*/}" "$r/log.restart"; then
            for e in punchForceZ drawInX drawInDiagonal movedSince; do
                checkClose "square cup: restart at t = ${tr##*/}: $e vs the continuous run" \
                    "$(summaryValue "$r" $e)" "$(v $e)" 1e-10
            done
        else
            fail "square cup: restart at t = '${tr##*/}' (see $r/log.restart)"
        fi
    else
        fail "square cup: no written time in the middle of the run to restart from"
    fi
    echo "    square cup: $(v steps) steps, $(v newtonIterationsPerStep) Newton its/step," \
         "$(v cutbacks) cutbacks, punch force $(v punchForceZ), draw-in x $(v drawInX)," \
         "diagonal $(v drawInDiagonal), wall time $(v wallTime) s"
else
    fail "square cup run (see $c/log.formFoam)"
    tail -15 "$c/log.formFoam" 2>/dev/null | sed 's/^/    | /'
fi

# The Newton matrix against central differences along every Newton update
# (formFoam -checkTangent, newtonTangentCheck.H) over the first 4 steps:
# shells, contact with friction on swept tools, the force-controlled
# holder. The median over the updates (observed 1.3e-6; 5e-5 before the
# swept punch face won the closest-point tie over its outline's start
# point, rigidProfile.H; single updates at friction's stick/slip corners
# reach 1e-2, so the median)
t=$work/tangent
if FORMFOAM_ARGS=-checkTangent runCopy squareCup "$t" blank \
       "sed -i 's/^endTime .*/endTime 0.02;/' system/controlDict" \
       "sed -i 's/forming { endTime 0.05;/forming { endTime 0.02;/; /drawing { endTime 0.1;/d' constant/processSchedule" \
       "sed -i '/movedSince/d' system/solidSolution" \
   && [ -f "$t/postProcessing/summary" ]; then
    checkBelow "square cup, -checkTangent: median error of the Newton matrix along the updates" \
        "$(updateTangentError "$t/log.formFoam" median)" 1e-5
    checkBetween "square cup, -checkTangent: every Newton update checked (checks, at least the converged steps' iterations)" \
        "$(summaryValue "$t" tangentChecks)" "$(summaryValue "$t" newtonIterations)" 1e9
else
    fail "square cup with -checkTangent (see $t/log.formFoam)"
fi
[ -n "${KEEP:-}" ] && echo "    kept $c" || rm -rf "$work"
