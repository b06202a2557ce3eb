#!/usr/bin/env bash
# Contact in 3D with rigid tools (contactModel3D.C, rigidSurface.H):
# 1. Hertz (tests/cases/hertz3D): a rigid sphere R = 50 pressed 0.04 into
#    a quarter of a linear elastic block 50 x 50 x 25 (E = 200000, nu =
#    0.3; symmetry x = 0, y = 0, bottom fixed; 27/4 hexahedra 0.35 wide
#    under the contact). From the total force P (4 x the quarter model's
#    toolForce), Hertz (Johnson, Contact Mechanics, 1985, sec. 4.2; rigid
#    sphere, BENCHMARKS.md): E* = E/(1 - nu^2), a = (3 P R/(4 E*))^(1/3),
#    p0 = 3 P/(2 pi a^2). FE: p0 = the largest nodal pressure; a = the
#    contact edge along y = 0, from the semi-ellipse p^2 = p0^2 (1 - x^2/
#    a^2) through the last two nodes carrying more than 1 % of p0 (as in
#    the 2D test, contact.sh). Within 3 %: observed +1.5 % (p0) and -1.6 %
#    (a). The force balances the bottom reaction (1e-9).
# 2. Sliding (tests/cases/slidingBlock3D): a block 2 x 2 x 1 pressed on
#    the plane z = 0 by its weight N = 400, its top dragged by 0.01 at 30
#    deg to x, Coulomb mu = 0.3: the ground's force on the block is
#    -mu N (cos 30, sin 30) (within 0.5 %: observed 1e-4), opposite to the
#    slip of the bottom (its direction within 1 deg of 30 deg), N = 400
#    (1e-8), and the drag balances it (1e-8).
# 3. Sticking: the same block dragged by 2e-4 (the friction force is then
#    0.17 mu N): the friction force balances the drag (1e-8) and stays
#    below mu N; the shear concentrates at the perimeter of the base,
#    whose nodes reach mu p and slip a little (partial slip, as in
#    Cattaneo-Mindlin), while the interior sticks: every interior node's
#    shear stays below 0.9 mu p (observed 0.57) and the base centre moves
#    by less than 1 % of the drag (observed 1e-13).
# 4. Bad input: a 2D profile for a 3D tool, an unknown surface type, a
#    sphere without radius, a plane whose normal points into its tool (the
#    whole patch on the tool's inner side), an unknown target patch; a
#    triSurface whose file is missing, has no triangles, or whose
#    triangles' normals point into the tool.
# 5. An STL sphere against the analytic one (below, after 1).
# 6. A force-controlled plane pressing a block (below, after 5).
. "$(dirname "$0")/testFunctions"

work=$(mktemp -d "${TMPDIR:-/tmp}/formFoamContact3D.XXXXXX")
pi=3.14159265358979

# 1. Hertz
c=$work/hertz
if runCopy hertz3D "$c" block; then
    Fq=$(summaryValue "$c" quarterForce)
    checkClose "Hertz 3D: force balances the bottom reaction" \
        "$(summaryValue "$c" bottomReaction)" "$Fq" 1e-9
    read -r p0FE aFE < <(awk '!/^#/ && NF >= 16 && $3 == 0 { x[++n] = $2; p[n] = $12 }
        END {
            for (i = 2; i <= n; ++i) { j = i; while (j > 1 && x[j-1] > x[j]) {
                t = x[j]; x[j] = x[j-1]; x[j-1] = t; t = p[j]; p[j] = p[j-1]; p[j-1] = t; --j } }
            pmax = 0; for (i = 1; i <= n; ++i) if (p[i] > pmax) pmax = p[i]
            last = 0; for (i = 1; i <= n; ++i) if (p[i] > 0.01*pmax) last = i
            if (last < 2 || last == n) { print pmax, "nan"; exit }
            x1 = x[last-1]; p1 = p[last-1]; x2 = x[last]; p2 = p[last]
            a2 = x2*x2 + p2*p2*(x2*x2 - x1*x1)/(p1*p1 - p2*p2)
            printf "%.10g %.10g\n", pmax, sqrt(a2) }' "$c/postProcessing/contact/1/blockTop.dat")
    read -r aRef p0Ref < <(awk -v F="$Fq" -v pi=$pi 'BEGIN { P = 4*F; Es = 200000/(1 - 0.09)
        a = (3*P*50/(4*Es))^(1/3); printf "%.10g %.10g\n", a, 3*P/(2*pi*a*a) }')
    echo "    Hertz 3D: P = $(calc "4*$Fq"), a = $aFE (Hertz $aRef), p0 = $p0FE (Hertz $p0Ref)"
    checkClose "Hertz 3D: peak pressure p0" "$p0FE" "$p0Ref" 0.03
    checkClose "Hertz 3D: contact radius a" "$aFE" "$aRef" 0.03
else
    fail "Hertz 3D run (see $c/log.formFoam)"
fi

# 5. The Hertz sphere as triangles (triSurface): the cap under the contact
#    zone written as an STL file (hertz3D/writeSphereCap.py: points on the
#    sphere, spacing h = 0.2 and 0.1) against the analytic sphere of 1,
#    all three on a coarser block (8 x 8 x 6 hexahedra instead of 12 x 12
#    x 8, 0.7 wide under the contact: a third of the time each; what is
#    compared is the facets, on the same mesh): the force converges to
#    the analytic one as the facets shrink (inscribed facets: below it),
#    at about second order in h (sagitta h^2/8R): observed -0.32 % and
#    -0.11 % (ratio 2.9; on the 12 x 12 x 8 block -0.53 % and -0.17 %,
#    ratio 3.0; there h = 0.05: -0.035 %)
coarse="sed -i 's/^n   12;/n   8;/; s/^nz  8;/nz  6;/' system/block/blockMeshDict"
c=$work/coarse
if runCopy hertz3D "$c" block "$coarse"; then
    Fc=$(summaryValue "$c" quarterForce)
else
    fail "Hertz 3D on the coarse block (see $c/log.formFoam)"
fi
rm -rf "$c"
if [ -n "${Fc:-}" ]; then
    declare -A stl
    for h in 0.2 0.1; do
        c=$work/stl$h
        if runCopy hertz3D "$c" block "$coarse" \
            "mkdir -p constant/triSurface && python3 writeSphereCap.py $h constant/triSurface/ball.stl" \
            "sed -i 's|surface { type sphere; centre (0 0 50); radius 50; }|surface { type triSurface; file \"ball.stl\"; }|' constant/contactProperties"
        then
            stl[$h]=$(calc "$(summaryValue "$c" quarterForce)/$Fc - 1")
        else
            fail "Hertz 3D with an STL sphere, h = $h (see $c/log.formFoam)"
        fi
        rm -rf "$c"
    done
    echo "    STL sphere: force error h = 0.2: ${stl[0.2]:-}, h = 0.1: ${stl[0.1]:-}"
    checkBetween "STL sphere h = 0.1: force within 0.4 % below the analytic sphere" "${stl[0.1]:-}" -0.004 0
    checkBetween "STL sphere: the error falls at about second order (ratio h = 0.2 / 0.1)" \
        "$(calc "${stl[0.2]:-nan}/${stl[0.1]:-nan}")" 2.5 6
else
    fail "STL sphere: no analytic Hertz force on the coarse block to compare with"
fi

# 6. A force-controlled plane pressing a linear elastic block (block3D,
#    1 x 1 x 3, E = 1000, nu = 0.3, symmetry planes x = 0, y = 0, z = 0),
#    starting 0.01 above it: the tool is moved onto the block before the
#    first step, then pushes with F = 5 (a nodal force: the whole face).
#    Frictionless: the uniaxial state, top at 3 - F L/E, side at
#    1 + nu F/E (to 1e-7: the gaps of the nodes, resolved to the
#    constraint's tolerance, differ by 1e-7); the tool stops on the top
#    face (within 1e-6; observed 1.2e-7) and the bottom reaction balances
#    F (1e-8).
c=$work/forceControl
if runCopy block3D "$c" block \
    "sed -i 's/type        neoHookean;/type        linearElastic;/' constant/block/solidProperties" \
    "sed -i '/^    bottom /,/translation/d' 0/block/D" \
    "sed -i 's/^    xMin .*/    xMin { type fixedDisplacement; components (x); }\n    bottom { type fixedDisplacement; components (z); }/' 0/block/D" \
    "sed -i 's/^    yMin .*/    yMin { type fixedDisplacement; components (y); }/' 0/block/D" \
    "sed -i 's/^    topZMax .*/    pressZ { type toolPosition; tool press; component z; }\n    pressForce { type toolForce; tool press; component z; }/' system/solidSolution" \
    "printf 'FoamFile { version 2.0; format ascii; class dictionary; object contactProperties; }\ntools { press { surface { type plane; point (0 0 3.01); normal (0 0 -1); } force table ((0 0) (1 5)); direction (0 0 -1); } }\npairs { top { patch top; tool press; friction 0; } }\n' > constant/contactProperties"
then
    z=$(summaryValue "$c" cornerZ)
    checkClose "force-controlled plane: top at 3 - F L/E" "$z" 2.985 1e-7
    checkClose "force-controlled plane: side at 1 + nu F/E" "$(summaryValue "$c" cornerX)" 1.0015 1e-7
    checkClose "force-controlled plane: bottom reaction = F" "$(summaryValue "$c" bottomReactionZ)" 5 1e-8
    gapTop=$(calc "3.01 + $(summaryValue "$c" pressZ) - $z")
    checkBetween "force-controlled plane: the tool rests on the top face (gap $gapTop)" "$gapTop" -1e-6 1e-6
else
    fail "force-controlled plane run (see $c/log.formFoam)"
fi

# 2. Sliding obliquely
muN=120
c=$work/sliding
if runCopy slidingBlock3D "$c" block; then
    checkClose "sliding 3D: normal force = weight" "$(summaryValue "$c" normalForce)" 400 1e-8
    checkClose "sliding 3D: friction x = -mu N cos 30" "$(summaryValue "$c" frictionX)" "$(calc "-$muN*0.866025403784439")" 0.005
    checkClose "sliding 3D: friction y = -mu N sin 30" "$(summaryValue "$c" frictionY)" "$(calc "-$muN*0.5")" 0.005
    checkClose "sliding 3D: drag x balances friction" "$(summaryValue "$c" topReactionX)" "$(calc "-1*$(summaryValue "$c" frictionX)")" 1e-8
    angle=$(calc "atan2($(summaryValue "$c" slipY), $(summaryValue "$c" slipX))*180/$pi")
    checkClose "sliding 3D: slip direction 30 deg (friction opposite)" "$angle" 30 0.033
else
    fail "sliding block 3D run (see $c/log.formFoam)"
fi

# 3. Sticking
c=$work/sticking
if runCopy slidingBlock3D "$c" block \
    "sed -i 's/(1 (0.008660254037844387 0.005 0))/(1 (0.00017320508075688773 0.0001 0))/' 0/block/D"; then
    Fx=$(summaryValue "$c" frictionX); Fy=$(summaryValue "$c" frictionY)
    checkClose "sticking 3D: friction x balances the drag" "$(summaryValue "$c" topReactionX)" "$(calc "-1*$Fx")" 1e-8
    checkClose "sticking 3D: friction y balances the drag" "$(summaryValue "$c" topReactionY)" "$(calc "-1*$Fy")" 1e-8
    checkBelow "sticking 3D: |friction| below mu N" "$(calc "sqrt($Fx*$Fx + $Fy*$Fy)")" $muN
    # Partial slip (Cattaneo-Mindlin): the shear concentrates at the
    # perimeter of the base, whose nodes reach mu p; the interior sticks
    slip=$(calc "sqrt($(summaryValue "$c" centreSlipX)^2 + $(summaryValue "$c" centreSlipY)^2)")
    checkBelow "sticking 3D: the base centre slips < 1 % of the 2e-4 drag" "$slip" 2e-6
    ratio=$(awk '!/^#/ && $2 > 0 && $2 < 2 && $3 > 0 && $3 < 2 { r = $13/(0.3*$12); if (r > m) m = r }
        END { printf "%.6g", m }' "$c/postProcessing/contact/1/blockBottom.dat")
    checkBelow "sticking 3D: interior base nodes inside the cone (largest shear/(mu p) $ratio)" "$ratio" 0.9
else
    fail "sticking block 3D run (see $c/log.formFoam)"
fi

# 4. Bad input
bad()   # bad <label> <regex> <edit>
{
    local c=$work/bad
    rm -rf "$c"; mkdir -p "$c"; cp -r "$formFoamTop/tests/cases/slidingBlock3D/." "$c/"
    (cd "$c" && eval "$3" && blockMesh -region block > log.blockMesh 2>&1)
    (cd "$c" && timeout 120 formFoam > log.formFoam 2>&1)
    expectFailure "$1" $? "$c/log.formFoam" "$2"
}
bad "3D tool given as a 2D profile" "Unknown entry 'profile'|unknown entry 'profile'" \
    "sed -i 's/ground { surface { type plane; point (0 0 0); normal (0 0 1); } }/ground { profile ((1 0) (-1 0)); }/' constant/contactProperties"
bad "unknown surface type" "unknown surface type 'cone'; valid: cylinder extrudedProfile pathProfile plane revolvedProfile sphere sweptProfile triSurface" \
    "sed -i 's/type plane; point (0 0 0); normal (0 0 1);/type cone; point (0 0 0);/' constant/contactProperties"
bad "sphere without radius" "missing entry 'radius'" \
    "sed -i 's/type plane; point (0 0 0); normal (0 0 1);/type sphere; centre (0 0 -5);/' constant/contactProperties"
bad "plane facing into its tool" "Tool 'ground' in .*contactProperties.* turns its back on patch 'bottom' of pair 'blockBottom'" \
    "sed -i 's/normal (0 0 1);/normal (0 0 -1);/' constant/contactProperties"
bad "unknown deformable target in 3D" "Unknown patch 'topp'.*entry 'targetPatch'" \
    "sed -i 's/blockBottom { patch bottom; tool ground; friction 0.3; }/blockBottom { patch bottom; targetPatch topp; }/' constant/contactProperties"
bad "triSurface: missing file" "Entry 'file' in .*contactProperties.*: no file .*constant/triSurface/ground.stl" \
    "sed -i 's/type plane; point (0 0 0); normal (0 0 1);/type triSurface; file \"ground.stl\";/' constant/contactProperties"
bad "triSurface: a file without triangles" "ground.stl has no triangles" \
    "sed -i 's/type plane; point (0 0 0); normal (0 0 1);/type triSurface; file \"ground.stl\";/' constant/contactProperties && mkdir -p constant/triSurface && printf 'solid ground\nendsolid ground\n' > constant/triSurface/ground.stl"
# the ground as two triangles whose normals point down, into the ground
bad "triSurface: normals into the tool" "Tool 'ground' in .*contactProperties.* turns its back on patch 'bottom' of pair 'blockBottom'" \
    "sed -i 's/type plane; point (0 0 0); normal (0 0 1);/type triSurface; file \"ground.stl\";/' constant/contactProperties && mkdir -p constant/triSurface && printf 'solid ground\nfacet normal 0 0 -1\nouter loop\nvertex -9 -9 0\nvertex 9 9 0\nvertex 9 -9 0\nendloop\nendfacet\nfacet normal 0 0 -1\nouter loop\nvertex -9 -9 0\nvertex -9 9 0\nvertex 9 9 0\nendloop\nendfacet\nendsolid ground\n' > constant/triSurface/ground.stl"
rm -rf "$work"
