#!/usr/bin/env bash
# Nothing lost: runs killed at every point of writing a time, a restart
# from a time that was not written, two runs in one case, a full disk.
#
# The case: tests/cases/slidingBlock made elasto-plastic (linear hardening,
# sigmaY0 150, H 2000: the push yields the block), i.e. plasticity,
# Coulomb friction against a rigid tool, three process steps with a
# prescribed ramp, the extrapolating predictor and step growth; 46
# converged steps, each written.
#
# Fault injection (formSceneIO.C): FORMFOAM_FAULT=<point>:<n> makes formFoam
# kill itself with SIGKILL at that point of its n-th time write:
#   region   after the first region's files, under .T.writing
#   rename   every file written and checked, before the rename
#   swap     an earlier version of the time moved aside (.T.old), the
#            new one not yet in place (only when a time is rewritten)
#   written  after the rename
# After each kill, startFrom latestTime must reproduce the uninterrupted
# run (also for the hydrostatic bulge, 1b): every history.dat line and summary value (totals of steps, Newton
# iterations and cutbacks included; wall times excepted) to 1e-10
# (compareRuns.py), and the VTK series must hold the same frames.
. "$(dirname "$0")/testFunctions"
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamFaults.XXXXXX")

plastic="type elastoPlastic; E 200000; nu 0.3; hardening { type linear; sigmaY0 150; H 2000; }"
prepare()
{
    rm -rf "$1"; mkdir -p "$1"
    cp -r "$here/slidingBlock/." "$1/"
    (
        cd "$1" || exit 1
        sed -i "/^material/,/^}/c\\material { $plastic }" constant/block/solidProperties
        sed -i 's/^writeControl .*/writeControl    timeStep;/' system/controlDict
        blockMesh -region block > log.blockMesh 2>&1
    )
}
# latest <case>: restart it from its latest time
latest()
{
    sed -i 's/^startFrom .*/startFrom       latestTime;/' "$1/system/controlDict"
    (cd "$1" && timeout 300 formFoam > log.restart 2>&1)
}
frames() { grep -o 'timestep="[^"]*"' "$1/VTK/block.pvd" 2>/dev/null | tr '\n' ' '; }

ref=$work/reference
prepare "$ref"
(cd "$ref" && timeout 300 formFoam > log.formFoam 2>&1)
rc=$?
steps=$(summaryValue "$ref" steps)
if [ $rc -eq 0 ] && [ "$(ls -d "$ref"/[0-9]* | grep -vc '/0$')" = "$steps" ]; then
    pass "uninterrupted plastic sliding block ran ($steps steps, each written)"
else
    fail "uninterrupted plastic sliding block (exit $rc, see $ref/log.formFoam)"
fi
# the material did yield (otherwise the history would not be tested)
epsMax=$(python3 - "$ref/3/block/epsilonEq" <<'PYTHON'
import re, sys
text = open(sys.argv[1]).read()
body = text.split("internalField", 1)[1].split("(", 1)[1].split(")", 1)[0]
print(max(float(v) for v in body.split()))
PYTHON
)
checkBelow "the block yields (max equivalent plastic strain > 1e-6)" "-$epsMax" -1e-6

# 1. Killed at each point of a write, then restarted from the latest time
for fault in region:10 rename:20 written:30 region:45; do
    c=$work/kill-${fault/:/-}
    prepare "$c"
    (cd "$c" && FORMFOAM_FAULT=$fault timeout 300 formFoam > log.formFoam 2>&1) 2>/dev/null
    rc=$?
    if [ $rc -eq 137 ] && grep -q "FORMFOAM_FAULT: killed at ${fault%%:*}" "$c/log.formFoam"; then
        pass "kill at $fault: the run died (SIGKILL)"
    else
        fail "kill at $fault: exit $rc, no kill logged (see $c/log.formFoam)"
    fi
    # every time directory present is complete
    incomplete=0
    for d in "$c"/[0-9]*; do
        [ "${d##*/}" = 0 ] && continue
        [ -f "$d/uniform/formFoamState" ] || incomplete=$((incomplete + 1))
    done
    checkBelow "kill at $fault: incomplete time directories" "$incomplete" 1
    if latest "$c"; then
        pass "kill at $fault: restart from the latest time ran"
    else
        fail "kill at $fault: restart (see $c/log.restart)"
        tail -10 "$c/log.restart" | sed 's/^/    | /'
    fi
    read -r diff n < <(python3 "$here/compareRuns.py" "$ref" "$c")
    checkBelow "kill at $fault: history and summary vs the uninterrupted run ($n values)" "$diff" 1e-10
    if [ "$(frames "$c")" = "$(frames "$ref")" ] && [ -n "$(frames "$ref")" ]; then
        pass "kill at $fault: the VTK series holds the frames of the uninterrupted run"
    else
        fail "kill at $fault: VTK frames $(frames "$c") vs $(frames "$ref")"
    fi
done

# 1b. The hydrostatic bulge (tutorials/hydraulicBulge: plasticity, contact
#     with the die, the oil cavity, quadratic predictor, step growth; 10
#     writes): killed after its 5th write, restarted from the latest time
bulge()
{
    rm -rf "$1"; mkdir -p "$1"
    cp -r "$formFoamTop/tutorials/hydraulicBulge/." "$1/"
    (cd "$1" && ./Allclean > /dev/null 2>&1; blockMesh -region blank > log.blockMesh 2>&1)
}
bref=$work/bulge
bulge "$bref"
(cd "$bref" && timeout 600 formFoam > log.formFoam 2>&1) \
    || fail "bulge: the uninterrupted run (see $bref/log.formFoam)"
c=$work/bulgeKilled
bulge "$c"
(cd "$c" && FORMFOAM_FAULT=written:5 timeout 600 formFoam > log.formFoam 2>&1) 2>/dev/null
rc=$?
[ $rc -eq 137 ] && pass "bulge: killed after its 5th write" \
    || fail "bulge: kill after the 5th write (exit $rc)"
if latest "$c"; then
    pass "bulge: restart from the latest time ran"
else
    fail "bulge: restart (see $c/log.restart)"
fi
read -r diff n < <(python3 "$here/compareRuns.py" "$bref" "$c")
checkBelow "bulge: history and summary vs the uninterrupted run ($n values)" "$diff" 1e-10
rm -rf "$bref" "$c"

# 2. Killed while rewriting a time (restart from t = 1.5 over the written
#    1.525, 1.55, ...): the earlier version of the time is put back
c=$work/swap
rm -rf "$c"; cp -r "$ref" "$c"; rm -f "$c"/log.*
sed -i 's/^startTime .*/startTime       1.5;/' "$c/system/controlDict"
(cd "$c" && FORMFOAM_FAULT=swap:1 timeout 300 formFoam > log.formFoam 2>&1) 2>/dev/null
rc=$?
if [ $rc -eq 137 ] && [ -d "$c/.1.525.old" ] && [ ! -d "$c/1.525" ]; then
    pass "kill while rewriting time 1.525: the run died with the old version aside"
else
    fail "kill while rewriting time 1.525: exit $rc (see $c/log.formFoam)"
fi
# (startTime is still 1.5) the restart after the kill
(cd "$c" && timeout 300 formFoam > log.restart 2>&1)
rc=$?
if [ $rc -eq 0 ] && grep -q 'Restoring time 1.525' "$c/log.restart" && [ -f "$c/1.525/uniform/formFoamState" ]; then
    pass "restart after the kill: time 1.525 restored, run finished"
else
    fail "restart after the kill while rewriting (exit $rc, see $c/log.restart)"
fi
read -r diff n < <(python3 "$here/compareRuns.py" "$ref" "$c")
checkBelow "rewritten run vs the uninterrupted run ($n values)" "$diff" 1e-10

# 3. A restart from a time that was not written stops, listing the
#    written times, and leaves postProcessing untouched
c=$work/notWritten
rm -rf "$c"; cp -r "$ref" "$c"; rm -f "$c"/log.*
before=$(md5sum < "$c/postProcessing/history.dat")
sed -i 's/^startTime .*/startTime       1.5125;/' "$c/system/controlDict"
(cd "$c" && timeout 60 formFoam > log.formFoam 2>&1)
expectFailure "restart from a time that was not written" $? "$c/log.formFoam" \
    "start time 1.5125.*has no time directory|complete written state"
grep -q ' 1.525' "$c/log.formFoam" \
    && pass "its message lists the written times" \
    || fail "its message lists the written times (see $c/log.formFoam)"
[ "$(md5sum < "$c/postProcessing/history.dat")" = "$before" ] \
    && pass "history.dat untouched by the failed restart" \
    || fail "history.dat changed by the failed restart"

# 4. An incomplete time directory (written by something else, or emptied)
#    is not a start: formFoam names it instead of starting from zero
c=$work/incomplete
rm -rf "$c"; cp -r "$ref" "$c"; rm -f "$c"/log.*
rm -rf "$c/3/block" "$c/3/uniform"
sed -i 's/^startFrom .*/startFrom       latestTime;/' "$c/system/controlDict"
(cd "$c" && timeout 60 formFoam > log.formFoam 2>&1)
expectFailure "restart from an emptied latest time" $? "$c/log.formFoam" \
    "start time directory .*/3.* holds no complete formFoam state"

# 5. Two runs in one case: the second is refused, naming the first
c=$work/twoRuns
prepare "$c"
(cd "$c" && timeout 300 formFoam > log.first 2>&1) &
first=$!
for _ in $(seq 100); do [ -f "$c/.formFoam.lock" ] && break; sleep 0.05; done
(cd "$c" && timeout 60 formFoam > log.second 2>&1)
expectFailure "a second run in the same case" $? "$c/log.second" \
    "Another formFoam run \\(PID $first|Another formFoam run \\(PID [0-9]+"
wait $first
rcFirst=$?
if [ $rcFirst -eq 0 ] && [ ! -e "$c/.formFoam.lock" ]; then
    pass "the first run finished and removed its lock"
else
    fail "the first run (exit $rcFirst, lock left: $(ls -a "$c" | grep -c formFoam.lock))"
fi
# a lock left by a killed run is stale: taken over
echo "$(hostname) 999999999" > "$c/.formFoam.lock"
(cd "$c" && timeout 300 formFoam > log.stale 2>&1)
rc=$?
if [ $rc -eq 0 ] && grep -q 'Removing the stale lock' "$c/log.stale"; then
    pass "a stale lock is taken over"
else
    fail "a stale lock (exit $rc, see $c/log.stale)"
fi

# 6. A full disk: the case on a 400 kB tmpfs; the run must stop naming the
#    last complete time, and every time directory left must be complete
d=$work/tmpfs
mkdir -p "$d"
if mount -t tmpfs -o size=400k tmpfs "$d" 2>/dev/null; then
    prepare "$work/small"
    cp -r "$work/small/." "$d/" 2>/dev/null
    (cd "$d" && timeout 300 formFoam > /tmp/formFoamDiskFull.log 2>&1)
    expectFailure "a full disk" $? /tmp/formFoamDiskFull.log \
        "failed.*disk full|Cannot (append|write).*disk full|cannot write file.*disk full"
    grep -q 'The last complete time is' /tmp/formFoamDiskFull.log \
        && pass "the message names the last complete time" \
        || fail "the message names the last complete time"
    bad=0
    for t in "$d"/[0-9]*; do
        [ "${t##*/}" = 0 ] && continue
        if [ ! -f "$t/uniform/formFoamState" ] || [ -n "$(find "$t" -type f -empty)" ]; then
            bad=$((bad + 1))
        fi
    done
    checkBelow "time directories left incomplete by the full disk" "$bad" 1
    umount "$d"
    rm -f /tmp/formFoamDiskFull.log
else
    for q in "a full disk" "the message names the last complete time" \
             "time directories left incomplete by the full disk"; do
        skip "$q: cannot mount a tmpfs here (not root?)"
    done
fi

rm -rf "$work"
