%
(bezcam 0.1.0: curve-semicircle.json, machine generic, output lines)
(tolerance 0.005 mm; largest deviation measured 0.004592 mm, proven bound 0.004713 mm, rounding included)
(T1: semicircle-r3)
(T1 plunge feed 200 mm/min)
(estimated cycle time 10 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.73 s; the exact path's bound on this machine 0.71 s [x1.028; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity semicircle-r3: bezier, degree 3, 2D)
G00 Z5.
X-3. Y0.
G01 Z-0.5 F200.
X-2.981 Y0.416 F800.
X-2.9 Y0.865
X-2.763 Y1.275
X-2.573 Y1.647
X-2.332 Y1.98
X-2.041 Y2.274
X-1.704 Y2.525
X-1.323 Y2.729
X-0.905 Y2.88
X-0.46 Y2.973
X0. Y3.004
X0.46 Y2.973
X0.905 Y2.88
X1.323 Y2.729
X1.704 Y2.525
X2.041 Y2.274
X2.332 Y1.98
X2.573 Y1.647
X2.763 Y1.275
X2.9 Y0.865
X2.981 Y0.416
X3. Y0.
G00 Z5.
M05
M30
%
