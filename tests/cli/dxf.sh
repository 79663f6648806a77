#!/usr/bin/env bash
# casteljau on DXF drawings: every MODEL-taking command reads them (one curve
# per curve entity, in the drawing's units or --units mm through $INSUNITS),
# convert --to dxf writes exact SPLINE entities that read back to the same
# doubles, and bad files are refused with one line naming the line, exit 2.
# Known values are worked by hand. Usage: bash dxf.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

# A line from (0,0) to (3,4) and a quarter arc of radius 2 about (0,0), in inches.
model part.dxf $'0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n1\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n3\n21\n4\n0\nARC\n10\n0\n20\n0\n40\n2\n50\n0\n51\n90\n0\nENDSEC\n0\nEOF\n'
check "eval reads each entity" $'0,0\n3,4\n2,0\n0,2' eval "$work/part.dxf" --at 0 --at 1
out=$("$casteljau" length "$work/part.dxf")
[[ "$(echo "$out" | head -1)" == 5 ]] || { echo "FAIL: the line's length: $out"; failures=$((failures + 1)); }
awk -v l="$(echo "$out" | tail -1)" 'BEGIN { d = l - 3.141592653589793; exit !(d < 1e-12 && d > -1e-12) }' ||
  { echo "FAIL: the arc's length is not pi: $out"; failures=$((failures + 1)); }
check "--units mm through \$INSUNITS (inches; 3 x 25.4 in double)" $'0,0\n76.19999999999999,101.6\n50.8,0\n0,50.8' eval "$work/part.dxf" --at 0 --at 1 --units mm
model unitless.dxf $'0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDSEC\n0\nEOF\n'
expect_error "--units mm without \$INSUNITS" "millimetres need the drawing's units, and its \$INSUNITS is 0 (unitless)" \
  length "$work/unitless.dxf" --units mm
model cut.dxf $'0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n'
expect_error "a file cut short" "cut.dxf, line 1: the ENTITIES section has no ENDSEC (the file is cut short)" \
  length "$work/cut.dxf"
model badcircle.dxf $'0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n5\n2A\n10\n0\n20\n0\n40\n0\n0\nENDSEC\n0\nEOF\n'
expect_error "an entity in error" "badcircle.dxf, line 5, CIRCLE (handle 2A): the radius must be > 0, got 0" \
  eval "$work/badcircle.dxf" --at 0

# convert --to dxf: exact, the same doubles back.
"$casteljau" convert "$examples/semicircle.json" --to dxf -o "$work/semi.dxf"
check "the NURBS semicircle reads back exactly" "$("$casteljau" convert "$examples/semicircle.json" --to json)" \
  convert "$work/semi.dxf" --to json
"$casteljau" convert "$work/part.dxf" --to dxf --units mm -o "$work/mm.dxf"
grep -q $'INSUNITS\r\?\n *70\r\?\n4$' "$work/mm.dxf" ||
  { echo "FAIL: a drawing read in mm is written with \$INSUNITS 4"; failures=$((failures + 1)); }
# The unit passes through (issue 39: --to step wrote inches under millimetres,
# --to dxf reset $INSUNITS to 0): the inch drawing keeps $INSUNITS 1 in DXF and
# is labelled inches in STEP and IGES; a drawing in metres is converted to
# millimetres (CAD files hold mm or inches); model JSON states no unit.
"$casteljau" convert "$work/part.dxf" --to dxf -o "$work/inches.dxf"
grep -q $'INSUNITS\r\?\n *70\r\?\n1$' "$work/inches.dxf" ||
  { echo "FAIL: a drawing in inches is written with \$INSUNITS 1"; failures=$((failures + 1)); }
check "--to step in inches" "convert: 2 curves and 0 surfaces to STEP AP214, exact (every knot, control point and weight as it is), in inches" \
  convert "$work/part.dxf" --to step -o "$work/part.stp"
grep -q "CONVERSION_BASED_UNIT('INCH'" "$work/part.stp" || { echo "FAIL: the STEP file is not in inches"; failures=$((failures + 1)); }
check "--to iges in inches" "convert: 2 curves and 0 surfaces to IGES 5.3 (entities 126 and 128), exact (every knot, control point and weight as it is), in inches" \
  convert "$work/part.dxf" --to iges -o "$work/part.igs"
model metres.dxf $'0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n6\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n3\n21\n4\n0\nENDSEC\n0\nEOF\n'
check "--to step from metres" "convert: 1 curve and 0 surfaces to STEP AP214, exact (knots and weights as they are, control points x 1000), converted from metres to millimetres" \
  convert "$work/metres.dxf" --to step -o "$work/metres.stp"
grep -q "CARTESIAN_POINT('',(3000.,4000.,0.))" "$work/metres.stp" ||
  { echo "FAIL: the metres are not millimetres in STEP"; failures=$((failures + 1)); }
"$casteljau" convert "$work/metres.dxf" --to dxf -o "$work/metres-back.dxf"
grep -q $'INSUNITS\r\?\n *70\r\?\n6$' "$work/metres-back.dxf" ||
  { echo "FAIL: a drawing in metres is written with \$INSUNITS 6"; failures=$((failures + 1)); }
model space.json '{"type": "bezier", "control_points": [[0,0,0],[1,1,1],[2,0,1]]}'
"$casteljau" convert "$work/space.json" --to dxf -o "$work/space.dxf"
check "a space curve reads back" "$("$casteljau" eval "$work/space.json" --samples 5)" eval "$work/space.dxf" --samples 5
expect_error "a surface to dxf" "is a surface; surfaces go to iges and step" convert "$examples/patch.json" --to dxf
finish dxf
