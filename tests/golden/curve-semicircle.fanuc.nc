%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output lines)
N20 (tolerance 0.005 mm; largest deviation measured 0.004783 mm, proven bound 0.004946 mm, rounding included)
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
N190 X-2.542 Y1.697
N200 X-2.289 Y2.029
N210 X-1.986 Y2.321
N220 X-1.633 Y2.568
N230 X-1.235 Y2.766
N240 X-0.795 Y2.908
N250 X-0.333 Y2.988
N260 X0.141 Y3.001
N270 X0.616 Y2.947
N280 X1.068 Y2.829
N290 X1.486 Y2.65
N300 X1.862 Y2.417
N310 X2.191 Y2.134
N320 X2.467 Y1.807
N330 X2.688 Y1.439
N340 X2.852 Y1.032
N350 X2.958 Y0.584
N360 X3.003 Y0.097
N370 X3. Y0.
N380 G00 Z5.
N390 M05
N400 M30
%
