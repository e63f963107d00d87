%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-rational-quarter-circle.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009731 mm, proven bound 0.009992 mm, rounding included)
N30 (T1: quarter-circle-r10)
N40 (estimated cycle time 8 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 (cutting along the curves 1.00 s; the exact path's bound on this machine 0.94 s [x1.066; rapids, plunges and pauses not counted])
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S12000 M03
N130 (entity quarter-circle-r10: bezier, degree 2, rational, 2D)
N140 G00 Z5.
N150 X10. Y0.
N160 G01 Z-1. F300.
N170 X9.956 Y1.032 F1000.
N180 X9.759 Y2.224
N190 X9.421 Y3.38
N200 X8.948 Y4.484
N210 X8.349 Y5.52
N220 X7.621 Y6.489
N230 X6.794 Y7.35
N240 X5.873 Y8.105
N250 X4.847 Y8.757
N260 X3.769 Y9.272
N270 X2.632 Y9.657
N280 X1.459 Y9.902
N290 X0.242 Y10.006
N300 X0. Y10.
N310 G00 Z5.
N320 M05
N330 M30
%
