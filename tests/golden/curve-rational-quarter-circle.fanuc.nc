%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-rational-quarter-circle.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009658 mm, proven bound 0.009987 mm, rounding included)
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
N160 X9.962 Y0.866 F1000.
N170 X9.851 Y1.718
N180 X9.666 Y2.562
N190 X9.41 Y3.383
N200 X9.084 Y4.181
N210 X8.684 Y4.959
N220 X8.218 Y5.697
N230 X7.694 Y6.388
N240 X7.114 Y7.028
N250 X6.483 Y7.614
N260 X5.8 Y8.146
N270 X5.077 Y8.616
N280 X4.332 Y9.013
N290 X3.531 Y9.356
N300 X2.719 Y9.623
N310 X1.896 Y9.819
N320 X1.052 Y9.945
N330 X0.206 Y9.998
N340 X0. Y10.
N350 G00 Z5.
N360 M05
N370 M30
%
