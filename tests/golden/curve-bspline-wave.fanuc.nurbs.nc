%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-bspline-wave.json, machine fanuc, output nurbs)
N20 (tolerance 0.01 mm; largest deviation measured below 1.432e-14 mm, proven bound 1.433e-14 mm, rounding included)
N30 (T1: wave)
N40 (T1 plunge feed 300 mm/min)
N50 (estimated cycle time 18 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 11.24 s; the exact path's bound on this machine 11.19 s [x1.004; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity wave: bspline, degree 3, 2D)
N150 G00 Z5.
N160 X0. Y0.
N170 G01 Z-1. F300.
N180 G06.2 P4 K0. X0. Y0. Z-1. R1. F1200.
N190 K0. X25. Y30. Z-1. R1.
N200 K0. X50. Y-10. Z-1. R1.
N210 K0. X80. Y35. Z-1. R1.
N220 K0.75 X110. Y-20. Z-1. R1.
N230 K1.5 X140. Y25. Z-1. R1.
N240 K2.5 X170. Y-5. Z-1. R1.
N250 K3.5 X200. Y10. Z-1. R1.
N260 K5.
N270 K5.
N280 K5.
N290 K5.
N300 G00 Z5.
N310 M05
N320 M30
%
