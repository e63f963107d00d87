%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-rational-quarter-circle.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009731 mm, proven bound 0.009992 mm, rounding included)
N30 (T1: quarter-circle-r10)
N40 (T1 plunge feed 300 mm/min)
N50 (estimated cycle time 8 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 1.00 s; the exact path's bound on this machine 0.94 s [x1.066; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity quarter-circle-r10: bezier, degree 2, rational, 2D)
N150 G00 Z5.
N160 X10. Y0.
N170 G01 Z-1. F300.
N180 X9.956 Y1.032 F1000.
N190 X9.759 Y2.224
N200 X9.421 Y3.38
N210 X8.948 Y4.484
N220 X8.349 Y5.52
N230 X7.621 Y6.489
N240 X6.794 Y7.35
N250 X5.873 Y8.105
N260 X4.847 Y8.757
N270 X3.769 Y9.272
N280 X2.632 Y9.657
N290 X1.459 Y9.902
N300 X0.242 Y10.006
N310 X0. Y10.
N320 G00 Z5.
N330 M05
N340 M30
%
