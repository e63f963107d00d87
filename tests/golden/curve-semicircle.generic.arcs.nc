%
(bezcam 0.1.0: curve-semicircle.json, machine generic, output arcs)
(tolerance 0.005 mm; largest deviation measured 0.004879 mm, proven bound 0.004892 mm, rounding included)
(T1: semicircle-r3)
(T1 plunge feed 200 mm/min)
(estimated cycle time 10 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.72 s; the exact path's bound on this machine 0.71 s [x1.015; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity semicircle-r3: bezier, degree 3, 2D)
G00 Z5.
X-3. Y0.
G01 Z-0.5 F200.
G02 X-2.372 Y1.925 I3.023 J0.079 F800.
G02 X-0.267 Y2.989 I2.286 J-1.909
G02 X2.131 Y2.187 I0.295 J-3.104
G02 X2.995 Y0.19 I-2.031 J-2.064
G01 X3. Y0.
G00 Z5.
M05
M30
%
