%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output lines)
N20 (tolerance 0.005 mm; largest deviation measured 0.004755 mm, proven bound 0.004953 mm, rounding included)
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
N160 X-2.978 Y0.446 F800.
N170 X-2.89 Y0.904
N180 X-2.742 Y1.323
N190 X-2.541 Y1.697
N200 X-2.288 Y2.031
N210 X-1.983 Y2.323
N220 X-1.625 Y2.573
N230 X-1.221 Y2.772
N240 X-0.777 Y2.913
N250 X-0.309 Y2.99
N260 X0.17 Y3.
N270 X0.64 Y2.943
N280 X1.09 Y2.821
N290 X1.506 Y2.639
N300 X1.877 Y2.406
N310 X2.198 Y2.127
N320 X2.468 Y1.805
N330 X2.685 Y1.443
N340 X2.848 Y1.044
N350 X2.955 Y0.604
N360 X3.002 Y0.12
N370 X3. Y0.
N380 G00 Z5.
N390 M05
N400 M30
%
