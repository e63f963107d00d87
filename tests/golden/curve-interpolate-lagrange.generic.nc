%
(bezcam 0.1.0: curve-interpolate-lagrange.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009595 mm, proven bound 0.009998 mm, rounding included)
(T1: arch)
(T1 plunge feed 300 mm/min)
(estimated cycle time 16 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 7.75 s; the exact path's bound on this machine 7.72 s [x1.003; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity arch: interpolate, degree 4, 2D)
G00 Z5.
X0. Y0.
G01 Z-1. F300.
X1.656 Y2.738 F1000.
X3.752 Y5.921
X6. Y9.067
X8.289 Y12.026
X10.666 Y14.863
X13.082 Y17.523
X15.523 Y19.996
X17.968 Y22.27
X20.431 Y24.364
X22.879 Y26.259
X25.327 Y27.973
X27.764 Y29.506
X30.178 Y30.858
X32.571 Y32.037
X34.999 Y33.074
X37.38 Y33.936
X39.785 Y34.653
X42.161 Y35.211
X44.551 Y35.624
X46.891 Y35.884
X49.237 Y36.001
X51.583 Y35.976
X53.928 Y35.809
X56.265 Y35.5
X58.662 Y35.035
X61.043 Y34.423
X63.405 Y33.668
X65.812 Y32.745
X68.189 Y31.68
X70.601 Y30.44
X73.041 Y29.019
X75.431 Y27.461
X77.834 Y25.726
X80.241 Y23.812
X82.641 Y21.722
X85.09 Y19.394
X87.501 Y16.901
X89.854 Y14.262
X92.195 Y11.419
X94.491 Y8.402
X96.698 Y5.259
X98.764 Y2.067
X100. Y0.
G00 Z5.
M05
M30
%
