%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-bspline-wave.json, machine fanuc, output nurbs)
N20 (tolerance 0.01 mm; largest deviation measured below 1e-05 mm, proven bound 1.432e-14 mm, rounding included)
N30 G21 G90 G17
N40 G40 G49 G80 G94
N50 G54
N60 T1 M06
N70 G43 H1
N80 S12000 M03
N90 (entity wave: bspline, degree 3, 2D)
N100 G00 Z5.
N110 X0. Y0.
N120 G01 Z-1. F300.
N130 G06.2 P4 K0. X0. Y0. Z-1. R1. F1200.
N140 K0. X25. Y30. Z-1. R1.
N150 K0. X50. Y-10. Z-1. R1.
N160 K0. X80. Y35. Z-1. R1.
N170 K0.75 X110. Y-20. Z-1. R1.
N180 K1.5 X140. Y25. Z-1. R1.
N190 K2.5 X170. Y-5. Z-1. R1.
N200 K3.5 X200. Y10. Z-1. R1.
N210 K5.
N220 K5.
N230 K5.
N240 K5.
N250 G00 Z5.
N260 M05
N270 M30
%
