%
(bezcam 0.1.0: curve-exercise-7.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009371 mm, proven bound 0.009979 mm, rounding included)
(T1: seed-ex-7)
(T1 plunge feed 200 mm/min)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.36 s; the exact path's bound on this machine 0.34 s [x1.044; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-7: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.662 Y0.621 F600.
X1.082 Y0.893
X1.34 Y0.938
X1.574 Y0.836
X1.821 Y0.719
X2.116 Y0.695
X2.519 Y0.785
X3. Y1.
G00 Z5.
M05
M30
%
