%
(bezcam 0.1.0: curve-semicircle.json, machine generic, output lines)
(tolerance 0.005 mm; largest deviation measured 0.0046 mm, proven bound 0.004982 mm, rounding included)
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
X-2.98 Y0.43 F800.
X-2.894 Y0.888
X-2.75 Y1.305
X-2.55 Y1.683
X-2.297 Y2.02
X-1.993 Y2.315
X-1.639 Y2.565
X-1.241 Y2.763
X-0.806 Y2.906
X-0.346 Y2.986
X0.127 Y3.002
X0.595 Y2.951
X1.043 Y2.837
X1.459 Y2.664
X1.834 Y2.438
X2.161 Y2.164
X2.445 Y1.837
X2.667 Y1.479
X2.836 Y1.081
X2.948 Y0.644
X3.001 Y0.166
X3. Y0.
G00 Z5.
M05
M30
%
