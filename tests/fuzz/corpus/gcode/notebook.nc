(casteljau 0.1.0: RS-274/NGC program for GRBL)
(source: ../../examples/notebook_curve.json)
(tolerance 0.01 mm: the path within it of the curves; the rounding of its numbers to 4 decimals takes at most 0.0005 of it)
(units mm [G21], absolute [G90], XY plane [G17], feed per minute [G94])
(depth 1.0000 in 1 pass, safe height 5.0000, feed 600.0000, plunge feed 200.0000)
(1 contour: 8 arcs [G2 G3], 0 lines [G1])
(box of the cuts: X 0.0000 to 4.0000, Y 0.0000 to 1.5481)
(cuts 5.4056 mm, plunges 6.0000, rapid moves 0.0000 in the plane [0.0000 in the input's order]; about 2 s at the feeds, rapid moves not counted)
G21 G90 G17 G94
G0 Z5.0000
G0 X0.0000 Y0.0000
G1 Z-1.0000 F200.0000
G2 X0.4804 Y0.7952 I5.2098 J-2.6049 F600.0000
G2 X1.1699 Y1.3805 I1.5222 J-1.0944
G2 X2.2424 Y1.5080 I0.7154 J-1.4432
G2 X3.2705 Y1.0518 I-0.6458 J-2.8417
G2 X3.7089 Y0.6709 I-1.6151 J-2.3016
G2 X3.9781 Y0.1742 I-0.8174 J-0.7644
G2 X3.9943 Y0.0877 I-0.7582 J-0.1868
G2 X4.0000 Y0.0000 I-0.6769 J-0.0877
G0 Z5.0000
M2
