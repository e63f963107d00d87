%
(bezcam 0.1.0: curve-exercise-8.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009543 mm, proven bound 0.009955 mm, rounding included)
(T1: seed-ex-8)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-8: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.349 Y0.031 F600.
X0.511 Y0.099
X0.572 Y0.189
X0.562 Y0.314
X0.442 Y0.522
X0.056 Y0.944
X-0.414 Y1.442
X-0.555 Y1.667
X-0.575 Y1.801
X-0.521 Y1.893
X-0.373 Y1.963
X-0.056 Y1.999
X0. Y2.
G00 Z5.
M05
M30
%
