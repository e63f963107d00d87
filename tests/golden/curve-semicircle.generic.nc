%
(bezcam 0.1.0: curve-semicircle.json, machine generic, output lines)
(tolerance 0.005 mm; largest deviation measured 0.004446 mm, proven bound 0.004635 mm, rounding included)
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
X-2.983 Y0.399 F800.
X-2.909 Y0.83
X-2.783 Y1.225
X-2.609 Y1.586
X-2.387 Y1.912
X-2.121 Y2.202
X-1.81 Y2.454
X-1.459 Y2.664
X-1.072 Y2.827
X-0.655 Y2.94
X-0.221 Y2.997
X0.221
X0.655 Y2.94
X1.072 Y2.827
X1.459 Y2.664
X1.81 Y2.454
X2.121 Y2.202
X2.387 Y1.912
X2.609 Y1.586
X2.783 Y1.225
X2.909 Y0.83
X2.983 Y0.399
X3. Y0.
G00 Z5.
M05
M30
%
