%
(bezcam 0.1.0: path-closed-teardrop.json, machine linuxcnc, output arcs)
(tolerance 0.01 mm; largest deviation measured 0.009985 mm, proven bound 0.009997 mm, rounding included)
(T2: teardrop)
(T2 plunge feed 300 mm/min)
(estimated cycle time 9 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 7.09 s; the exact path's bound on this machine 7.05 s [x1.004; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T2 M6
G43 H2
S12000 M3
(entity teardrop: path, degree 3, 2D)
G0 Z5.
X0. Y0.
G1 Z-1. F300.
G3 X13.2046 Y7.5531 I-54.0976 J109.8941 F1000.
G3 X21.5086 Y14.0393 I-35.6076 J54.1456
G3 X26.7203 Y20.0807 I-23.6597 J25.6791
G3 X29.5607 Y26.3696 I-16.5665 J11.2682
G3 X29.9957 Y29.6427 I-13.4667 J3.4552
G3 X30. Y30. I-167.8635 J2.1989
G3 X28.5874 Y35.9482 I-12.6454 J0.1388
G3 X21.7286 Y41.4176 I-9.8975 J-5.3765
G3 X14.3498 Y41.5663 I-3.9769 J-14.1949
G3 X10.779 Y40.3694 I4.8054 J-20.2613
G3 X10. Y40. I6.0174 J-13.6957
G3 X2.421 Y34.0099 I11.1997 J-21.9602
G3 X-4.1218 Y15.0652 I20.6575 J-17.7365
G3 X-1.9053 Y4.3712 I34.2449 J1.5211
G3 X0. Y0. I47.7286 J18.2029
G0 Z5.
M5
M30
%
