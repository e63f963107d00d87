%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-rational-quarter-circle.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009731 mm, proven bound 0.009992 mm, rounding included)
N30 (T1: quarter-circle-r10)
N40 (estimated cycle time 8 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity quarter-circle-r10: bezier, degree 2, rational, 2D)
N130 G00 Z5.
N140 X10. Y0.
N150 G01 Z-1. F300.
N160 X9.956 Y1.032 F1000.
N170 X9.759 Y2.224
N180 X9.421 Y3.38
N190 X8.948 Y4.484
N200 X8.349 Y5.52
N210 X7.621 Y6.489
N220 X6.794 Y7.35
N230 X5.873 Y8.105
N240 X4.847 Y8.757
N250 X3.769 Y9.272
N260 X2.632 Y9.657
N270 X1.459 Y9.902
N280 X0.242 Y10.006
N290 X0. Y10.
N300 G00 Z5.
N310 M05
N320 M30
%
