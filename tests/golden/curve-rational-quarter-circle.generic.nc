%
(bezcam 0.1.0: curve-rational-quarter-circle.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009731 mm, proven bound 0.009992 mm, rounding included)
(T1: quarter-circle-r10)
(T1 plunge feed 300 mm/min)
(estimated cycle time 10 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.97 s; the exact path's bound on this machine 0.94 s [x1.025; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity quarter-circle-r10: bezier, degree 2, rational, 2D)
G00 Z5.
X10. Y0.
G01 Z-1. F300.
X9.956 Y1.032 F1000.
X9.759 Y2.224
X9.421 Y3.38
X8.948 Y4.484
X8.349 Y5.52
X7.621 Y6.489
X6.794 Y7.35
X5.873 Y8.105
X4.847 Y8.757
X3.769 Y9.272
X2.632 Y9.657
X1.459 Y9.902
X0.242 Y10.006
X0. Y10.
G00 Z5.
M05
M30
%
