%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output lines)
N20 (tolerance 0.005 mm; largest deviation measured 0.004592 mm, proven bound 0.004713 mm, rounding included)
N30 (T1: semicircle-r3)
N40 (estimated cycle time 8 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 (cutting along the curves 0.76 s; the exact path's bound on this machine 0.71 s [x1.067; rapids, plunges and pauses not counted])
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S12000 M03
N130 (entity semicircle-r3: bezier, degree 3, 2D)
N140 G00 Z5.
N150 X-3. Y0.
N160 G01 Z-0.5 F200.
N170 X-2.981 Y0.416 F800.
N180 X-2.9 Y0.865
N190 X-2.763 Y1.275
N200 X-2.573 Y1.647
N210 X-2.332 Y1.98
N220 X-2.041 Y2.274
N230 X-1.704 Y2.525
N240 X-1.323 Y2.729
N250 X-0.905 Y2.88
N260 X-0.46 Y2.973
N270 X0. Y3.004
N280 X0.46 Y2.973
N290 X0.905 Y2.88
N300 X1.323 Y2.729
N310 X1.704 Y2.525
N320 X2.041 Y2.274
N330 X2.332 Y1.98
N340 X2.573 Y1.647
N350 X2.763 Y1.275
N360 X2.9 Y0.865
N370 X2.981 Y0.416
N380 X3. Y0.
N390 G00 Z5.
N400 M05
N410 M30
%
