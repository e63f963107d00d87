%
(bezcam 0.1.0: curve-interpolate-airfoil.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.00968 mm, proven bound 0.009958 mm, rounding included)
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
X0.617 Y2.206 F1200.
X1.142 Y3.656
X1.688 Y4.795
X2. Y5.3
X2.58 Y6.117
X3.412 Y7.03
X4.454 Y7.949
X5.747 Y8.884
X7.382 Y9.873
X8. Y10.2
X9.85 Y11.137
X12.134 Y12.13
X14.616 Y13.05
X17.365 Y13.909
X20. Y14.6
X23.017 Y15.297
X26.644 Y15.983
X30.468 Y16.556
X34.495 Y17.009
X38.719 Y17.337
X40. Y17.4
X43.892 Y17.555
X48.669 Y17.597
X53.869 Y17.495
X59.608 Y17.232
X60. Y17.2
X65.462 Y16.834
X72.09 Y16.243
X79.11 Y15.47
X86.604 Y14.496
X90. Y14.
X97.079 Y12.911
X105.294 Y11.499
X113.521 Y9.939
X120. Y8.6
X127.64 Y6.932
X138.133 Y4.485
X150. Y1.6
G00 Z5.
M05
M30
%
