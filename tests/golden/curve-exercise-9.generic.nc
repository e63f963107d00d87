%
(bezcam 0.1.0: curve-exercise-9.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009643 mm, proven bound 0.009992 mm, rounding included)
(T1: seed-ex-9)
(T1 plunge feed 200 mm/min)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.30 s; the exact path's bound on this machine 0.28 s [x1.059; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-9: bezier, degree 4, 2D)
G00 Z5.
X0. Y-1.
G01 Z-0.5 F200.
X0.34 Y-0.244 F600.
X0.39 Y0.084
X0.305 Y0.215
X0.01 Y0.259
X-0.261 Y0.262
X-0.382 Y0.353
X-0.366 Y0.535
X-0.104 Y0.905
X0. Y1.
G00 Z5.
M05
M30
%
