(bezcam 0.1.0: curve-semicircle.json, machine grbl, output nurbs)
(tolerance 0.005 mm; largest deviation measured 0.002522 mm, proven bound 0.002568 mm, rounding included)
(T1: semicircle-r3)
(T1 plunge feed 200 mm/min)
(estimated cycle time 6 s on the motion model of machine grbl [acceleration, corners, tool changes])
(cutting along the curves 0.74 s; the exact path's bound on this machine 0.71 s [x1.034; rapids, plunges and pauses not counted])
(machine grbl has no NURBS words: nurbs output cuts with arcs [G02/G03] and G01 lines)
G21 G90 G17
G40 G49 G80 G94
G54
(tool 1: load it before starting)
S12000 M3
G4 P2.
(entity semicircle-r3: bezier, degree 3, 2D)
G0 Z5.
X-3. Y0.
G1 Z-0.5 F200.
G2 X-2.782 Y1.215 I3.305 J0.035 F800.
G2 X-1.845 Y2.424 I2.465 J-0.943
G2 X-0.322 Y2.985 I1.797 J-2.531
G2 X0.966 Y2.857 I0.307 J-3.458
G2 X2.288 Y2.025 I-0.813 J-2.758
G2 X2.779 Y1.223 I-1.902 J-1.716
G2 X3. Y0. I-3.137 J-1.198
G0 Z5.
M5
M30
