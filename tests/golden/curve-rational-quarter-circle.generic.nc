%
(bezcam 0.1.0: curve-rational-quarter-circle.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009658 mm, proven bound 0.009987 mm, rounding included)
(T1: quarter-circle-r10)
(estimated cycle time 10 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity quarter-circle-r10: bezier, degree 2, rational, 2D)
G00 Z5.
X10. Y0.
G01 Z-1. F300.
X9.962 Y0.866 F1000.
X9.851 Y1.718
X9.666 Y2.562
X9.41 Y3.383
X9.084 Y4.181
X8.684 Y4.959
X8.218 Y5.697
X7.694 Y6.388
X7.114 Y7.028
X6.483 Y7.614
X5.8 Y8.146
X5.077 Y8.616
X4.332 Y9.013
X3.531 Y9.356
X2.719 Y9.623
X1.896 Y9.819
X1.052 Y9.945
X0.206 Y9.998
X0. Y10.
G00 Z5.
M05
M30
%
