%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output lines)
N20 (tolerance 0.005 mm; largest deviation measured 0.004592 mm, proven bound 0.004713 mm, rounding included)
N30 (T1: semicircle-r3)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 8 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.76 s; the exact path's bound on this machine 0.71 s [x1.067; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity semicircle-r3: bezier, degree 3, 2D)
N150 G00 Z5.
N160 X-3. Y0.
N170 G01 Z-0.5 F200.
N180 X-2.981 Y0.416 F800.
N190 X-2.9 Y0.865
N200 X-2.763 Y1.275
N210 X-2.573 Y1.647
N220 X-2.332 Y1.98
N230 X-2.041 Y2.274
N240 X-1.704 Y2.525
N250 X-1.323 Y2.729
N260 X-0.905 Y2.88
N270 X-0.46 Y2.973
N280 X0. Y3.004
N290 X0.46 Y2.973
N300 X0.905 Y2.88
N310 X1.323 Y2.729
N320 X1.704 Y2.525
N330 X2.041 Y2.274
N340 X2.332 Y1.98
N350 X2.573 Y1.647
N360 X2.763 Y1.275
N370 X2.9 Y0.865
N380 X2.981 Y0.416
N390 X3. Y0.
N400 G00 Z5.
N410 M05
N420 M30
%
