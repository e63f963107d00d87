%
(bezcam 0.1.0: curve-semicircle.json, machine generic, output lines)
(tolerance 0.005 mm; largest deviation measured 0.004863 mm, proven bound 0.004999 mm, rounding included)
(T1: semicircle-r3)
(estimated cycle time 10 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity semicircle-r3: bezier, degree 3, 2D)
G00 Z5.
X-3. Y0.
G01 Z-0.5 F200.
X-2.981 Y0.381 F800.
X-2.929 Y0.719
X-2.845 Y1.04
X-2.73 Y1.339
X-2.586 Y1.616
X-2.414 Y1.872
X-2.213 Y2.106
X-1.984 Y2.317
X-1.734 Y2.501
X-1.459 Y2.659
X-1.159 Y2.791
X-0.84 Y2.893
X-0.503 Y2.962
X-0.159 Y2.996
X0.189 Y2.995
X0.529 Y2.958
X0.865 Y2.886
X1.185 Y2.781
X1.483 Y2.647
X1.761 Y2.483
X2.011 Y2.295
X2.236 Y2.082
X2.432 Y1.848
X2.601 Y1.592
X2.741 Y1.315
X2.852 Y1.018
X2.934 Y0.697
X2.984 Y0.354
X3. Y0.
G00 Z5.
M05
M30
%
