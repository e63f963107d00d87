%
(bezcam 0.1.0: curve-semicircle.json, machine generic, output arcs)
(tolerance 0.005 mm; largest deviation measured 0.002522 mm, proven bound 0.002568 mm, rounding included)
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
G02 X-2.782 Y1.215 I3.305 J0.035 F800.
G02 X-1.845 Y2.424 I2.465 J-0.943
G02 X-0.322 Y2.985 I1.797 J-2.531
G02 X0.966 Y2.857 I0.307 J-3.458
G02 X2.288 Y2.025 I-0.813 J-2.758
G02 X2.779 Y1.223 I-1.902 J-1.716
G02 X3. Y0. I-3.137 J-1.198
G00 Z5.
M05
M30
%
