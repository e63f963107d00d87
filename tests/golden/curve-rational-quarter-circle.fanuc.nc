%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-rational-quarter-circle.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009879 mm, proven bound 0.009992 mm, rounding included)
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
N160 X9.955 Y1.036 F1000.
N170 X9.765 Y2.198
N180 X9.437 Y3.335
N190 X8.963 Y4.455
N200 X8.363 Y5.498
N210 X7.656 Y6.447
N220 X6.811 Y7.334
N230 X5.895 Y8.089
N240 X4.875 Y8.741
N250 X3.803 Y9.258
N260 X2.67 Y9.646
N270 X1.501 Y9.896
N280 X0.322 Y10.004
N290 X0. Y10.
N300 G00 Z5.
N310 M05
N320 M30
%
