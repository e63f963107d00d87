%
(bezcam 0.1.0: curve-exercise-5.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009438 mm, proven bound 0.009491 mm, rounding included)
(T1: seed-ex-5)
(T1 plunge feed 200 mm/min)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.39 s; the exact path's bound on this machine 0.36 s [x1.056; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-5: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.482 Y0.453 F600.
X0.96 Y0.795
X1.332 Y0.972
X1.5 Y1.
X1.332 Y1.028
X0.96 Y1.205
X0.482 Y1.547
X0. Y2.
G00 Z5.
M05
M30
%
