%
(bezcam 0.1.0: curve-rational-quarter-circle.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009879 mm, proven bound 0.009992 mm, rounding included)
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
X9.955 Y1.036 F1000.
X9.765 Y2.198
X9.437 Y3.335
X8.963 Y4.455
X8.363 Y5.498
X7.656 Y6.447
X6.811 Y7.334
X5.895 Y8.089
X4.875 Y8.741
X3.803 Y9.258
X2.67 Y9.646
X1.501 Y9.896
X0.322 Y10.004
X0. Y10.
G00 Z5.
M05
M30
%
