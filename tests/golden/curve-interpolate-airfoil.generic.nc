%
(bezcam 0.1.0: curve-interpolate-airfoil.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009359 mm, proven bound 0.009566 mm, rounding included)
(T1: upper-surface)
(estimated cycle time 17 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S18000 M03
(entity upper-surface: interpolate, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-1. F300.
X0.565 Y2.04 F1200.
X1.056 Y3.446
X1.543 Y4.523
X2. Y5.3
X2.509 Y6.027
X3.242 Y6.859
X4.141 Y7.692
X5.23 Y8.53
X6.571 Y9.403
X8. Y10.2
X9.507 Y10.974
X11.362 Y11.812
X13.331 Y12.593
X15.443 Y13.324
X17.78 Y14.026
X20. Y14.6
X22.677 Y15.225
X25.937 Y15.861
X29.341 Y16.402
X32.908 Y16.848
X36.652 Y17.195
X40. Y17.4
X43.205 Y17.537
X47.118 Y17.599
X51.291 Y17.563
X55.789 Y17.422
X60. Y17.2
X64.966 Y16.872
X70.968 Y16.353
X77.28 Y15.685
X83.945 Y14.858
X90. Y14.
X95.382 Y13.184
X101.697 Y12.136
X108.061 Y10.991
X114.472 Y9.75
X120. Y8.6
X126.879 Y7.104
X136.548 Y4.862
X150. Y1.6
G00 Z5.
M05
M30
%
