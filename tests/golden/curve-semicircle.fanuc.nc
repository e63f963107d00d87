%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output lines)
N20 (tolerance 0.005 mm; largest deviation measured 0.0046 mm, proven bound 0.004982 mm, rounding included)
N30 (T1: semicircle-r3)
N40 (estimated cycle time 8 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity semicircle-r3: bezier, degree 3, 2D)
N130 G00 Z5.
N140 X-3. Y0.
N150 G01 Z-0.5 F200.
N160 X-2.98 Y0.43 F800.
N170 X-2.894 Y0.888
N180 X-2.75 Y1.305
N190 X-2.55 Y1.683
N200 X-2.297 Y2.02
N210 X-1.993 Y2.315
N220 X-1.639 Y2.565
N230 X-1.241 Y2.763
N240 X-0.806 Y2.906
N250 X-0.346 Y2.986
N260 X0.127 Y3.002
N270 X0.595 Y2.951
N280 X1.043 Y2.837
N290 X1.459 Y2.664
N300 X1.834 Y2.438
N310 X2.161 Y2.164
N320 X2.445 Y1.837
N330 X2.667 Y1.479
N340 X2.836 Y1.081
N350 X2.948 Y0.644
N360 X3.001 Y0.166
N370 X3. Y0.
N380 G00 Z5.
N390 M05
N400 M30
%
