%
(bezcam 0.1.0: curve-nurbs-circle.json, machine generic, output arcs)
(tolerance 0.01 mm; largest deviation measured below 2.449e-06 mm, proven bound 2.449e-06 mm, rounding included)
(T1: circle-d80)
(T1 plunge feed 300 mm/min)
(estimated cycle time 24 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 15.09 s; the exact path's bound on this machine 15.07 s [x1.001; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity circle-d80: bspline, degree 2, rational, 2D)
G00 Z5.
X20. Y50.
G01 Z-1. F300.
G03 X60. Y10. I40. J0. F1000.
G03 X100. Y50. I0. J40.
G03 X60. Y90. I-40. J0.
G03 X20. Y50. I0. J-40.
G00 Z5.
M05
M30
%
