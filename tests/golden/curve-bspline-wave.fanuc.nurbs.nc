%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-bspline-wave.json, machine fanuc, output nurbs)
N20 (tolerance 0.01 mm; largest deviation measured below 1.432e-14 mm, proven bound 1.433e-14 mm, rounding included)
N30 (T1: wave)
N40 (estimated cycle time 18 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 (cutting along the curves 11.24 s; the exact path's bound on this machine 11.19 s [x1.004; rapids, plunges and pauses not counted])
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S12000 M03
N130 (entity wave: bspline, degree 3, 2D)
N140 G00 Z5.
N150 X0. Y0.
N160 G01 Z-1. F300.
N170 G06.2 P4 K0. X0. Y0. Z-1. R1. F1200.
N180 K0. X25. Y30. Z-1. R1.
N190 K0. X50. Y-10. Z-1. R1.
N200 K0. X80. Y35. Z-1. R1.
N210 K0.75 X110. Y-20. Z-1. R1.
N220 K1.5 X140. Y25. Z-1. R1.
N230 K2.5 X170. Y-5. Z-1. R1.
N240 K3.5 X200. Y10. Z-1. R1.
N250 K5.
N260 K5.
N270 K5.
N280 K5.
N290 G00 Z5.
N300 M05
N310 M30
%
