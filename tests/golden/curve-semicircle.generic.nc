%
(bezcam 0.1.0: curve-semicircle.json, machine generic, output lines)
(tolerance 0.005 mm; largest deviation measured 0.004755 mm, proven bound 0.004953 mm, rounding included)
(T1: semicircle-r3)
(estimated cycle time 10 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity semicircle-r3: bezier, degree 3, 2D)
G00 Z5.
X-3. Y0.
G01 Z-0.5 F200.
X-2.978 Y0.446 F800.
X-2.89 Y0.904
X-2.742 Y1.323
X-2.541 Y1.697
X-2.288 Y2.031
X-1.983 Y2.323
X-1.625 Y2.573
X-1.221 Y2.772
X-0.777 Y2.913
X-0.309 Y2.99
X0.17 Y3.
X0.64 Y2.943
X1.09 Y2.821
X1.506 Y2.639
X1.877 Y2.406
X2.198 Y2.127
X2.468 Y1.805
X2.685 Y1.443
X2.848 Y1.044
X2.955 Y0.604
X3.002 Y0.12
X3. Y0.
G00 Z5.
M05
M30
%
