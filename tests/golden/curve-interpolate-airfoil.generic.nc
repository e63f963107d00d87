%
(bezcam 0.1.0: curve-interpolate-airfoil.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009438 mm, proven bound 0.009589 mm, rounding included)
(T1: upper-surface)
(T1 plunge feed 300 mm/min)
(estimated cycle time 17 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 7.93 s; the exact path's bound on this machine 7.90 s [x1.003; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S18000 M03
(entity upper-surface: interpolate, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-1. F300.
X0.569 Y2.054 F1200.
X1.058 Y3.45
X1.546 Y4.529
X2. Y5.3
X2.508 Y6.026
X3.241 Y6.858
X4.136 Y7.688
X5.226 Y8.528
X6.563 Y9.398
X8. Y10.2
X9.506 Y10.973
X11.358 Y11.81
X13.325 Y12.591
X15.443 Y13.324
X17.769 Y14.023
X20. Y14.6
X22.676 Y15.225
X25.93 Y15.86
X29.337 Y16.402
X32.905 Y16.848
X36.646 Y17.194
X40. Y17.4
X43.2 Y17.536
X47.115 Y17.599
X51.277 Y17.563
X55.779 Y17.423
X60. Y17.2
X64.957 Y16.873
X70.965 Y16.353
X77.268 Y15.687
X83.932 Y14.86
X90. Y14.
X95.38 Y13.185
X101.696 Y12.136
X108.06 Y10.991
X114.469 Y9.75
X120. Y8.6
X126.862 Y7.108
X136.479 Y4.879
X150. Y1.6
G00 Z5.
M05
M30
%
