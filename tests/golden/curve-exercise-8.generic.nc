%
(bezcam 0.1.0: curve-exercise-8.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009338 mm, proven bound 0.009745 mm, rounding included)
(T1: seed-ex-8)
(T1 plunge feed 200 mm/min)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.35 s; the exact path's bound on this machine 0.33 s [x1.049; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-8: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.366 Y0.026 F600.
X0.55 Y0.124
X0.582 Y0.275
X0.448 Y0.529
X0. Y1.
X-0.448 Y1.471
X-0.582 Y1.725
X-0.55 Y1.876
X-0.366 Y1.974
X0. Y2.
G00 Z5.
M05
M30
%
