%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-interpolate-airfoil.json, machine fanuc, output nurbs)
N20 (tolerance 0.01 mm; largest deviation measured 0.0003806 mm, proven bound 0.0005211 mm, rounding included)
N30 (T1: upper-surface)
N40 (T1 plunge feed 300 mm/min)
N50 (estimated cycle time 15 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 7.94 s; the exact path's bound on this machine 7.90 s [x1.005; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S18000 M03
N140 (entity upper-surface: interpolate, degree 3, 2D)
N150 G00 Z5.
N160 X0. Y0.
N170 G01 Z-1. F300.
N180 G06.2 P4 K0. X0. Y0. Z-1. R1. F1200.
N190 K0. X0.501 Y1.873 Z-1. R1.
N200 K0. X1.688 Y6.309 Z-1. R1.
N210 K0. X9.435 Y11.465 Z-1. R1.
N220 K0.2871 X22.229 Y15.669 Z-1. R1.
N230 K0.6797 X39.946 Y17.894 Z-1. R1.
N240 K1.3275 X63.403 Y17.366 Z-1. R1.
N250 K2.351 X90.156 Y14.311 Z-1. R1.
N260 K3.3647 X120.171 Y8.878 Z-1. R1.
N270 K4.8938 X140.022 Y4.035 Z-1. R1.
N280 K6.4387 X150. Y1.6 Z-1. R1.
N290 K8.
N300 K8.
N310 K8.
N320 K8.
N330 G00 Z5.
N340 M05
N350 M30
%
