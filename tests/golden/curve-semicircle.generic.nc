%
(bezcam 0.1.0: curve-semicircle.json, machine generic, output lines)
(tolerance 0.005 mm; largest deviation measured 0.004783 mm, proven bound 0.004946 mm, rounding included)
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
X-2.542 Y1.697
X-2.289 Y2.029
X-1.986 Y2.321
X-1.633 Y2.568
X-1.235 Y2.766
X-0.795 Y2.908
X-0.333 Y2.988
X0.141 Y3.001
X0.616 Y2.947
X1.068 Y2.829
X1.486 Y2.65
X1.862 Y2.417
X2.191 Y2.134
X2.467 Y1.807
X2.688 Y1.439
X2.852 Y1.032
X2.958 Y0.584
X3.003 Y0.097
X3. Y0.
G00 Z5.
M05
M30
%
