%
(bezcam 0.1.0: curve-interpolate-airfoil.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009759 mm, proven bound 0.009999 mm, rounding included)
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
X0.622 Y2.223 F1200.
X1.163 Y3.707
X1.707 Y4.829
X2. Y5.3
X2.565 Y6.099
X3.406 Y7.024
X4.45 Y7.945
X5.737 Y8.877
X7.393 Y9.879
X8. Y10.2
X9.841 Y11.133
X12.164 Y12.142
X14.678 Y13.071
X17.458 Y13.936
X20. Y14.6
X22.951 Y15.283
X26.619 Y15.979
X30.474 Y16.557
X34.532 Y17.013
X38.685 Y17.335
X40. Y17.4
X43.863 Y17.554
X48.712 Y17.597
X53.955 Y17.492
X59.764 Y17.223
X60. Y17.2
X65.456 Y16.834
X72.205 Y16.231
X79.322 Y15.445
X86.901 Y14.454
X90. Y14.
X96.938 Y12.934
X105.028 Y11.547
X113.194 Y10.004
X120. Y8.6
X127.544 Y6.954
X138.759 Y4.335
X150. Y1.6
G00 Z5.
M05
M30
%
