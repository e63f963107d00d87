%
(bezcam 0.1.0: curve-cube-3d.json, machine generic, output lines)
(tolerance 0.001 mm; largest deviation measured 0.0008914 mm, proven bound 0.0009996 mm, rounding included)
(T1: cube-base-curve)
(T1 plunge feed 100 mm/min)
(estimated cycle time 11 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.28 s; the exact path's bound on this machine 0.25 s [x1.088; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity cube-base-curve: bezier, degree 3, 3D)
G00 Z5.
X0. Y0.
G01 Z0. F100.
X0.079 Y0.002 F500.
X0.153 Y0.008
X0.216 Y0.017
X0.278 Y0.03 Z0.001
X0.341 Y0.046 Z0.002
X0.409 Y0.069 Z0.004
X0.461 Y0.091 Z0.006
X0.513 Y0.117 Z0.01
X0.567 Y0.149 Z0.014
X0.615 Y0.182 Z0.02
X0.662 Y0.22 Z0.028
X0.705 Y0.26 Z0.037
X0.748 Y0.307 Z0.05
X0.786 Y0.355 Z0.065
X0.818 Y0.4 Z0.081
X0.847 Y0.447 Z0.1
X0.873 Y0.496 Z0.123
X0.897 Y0.547 Z0.15
X0.917 Y0.595 Z0.179
X0.934 Y0.642 Z0.211
X0.949 Y0.69 Z0.249
X0.961 Y0.733 Z0.289
X0.971 Y0.776 Z0.333
X0.979 Y0.815 Z0.381
X0.985 Y0.849 Z0.43
X0.99 Y0.881 Z0.483
X0.993 Y0.907 Z0.535
X0.996 Y0.932 Z0.593
X0.998 Y0.952 Z0.653
X0.999 Y0.969 Z0.716
X1. Y0.983 Z0.785
Y0.993 Z0.862
Y0.999 Z0.949
Y1. Z1.
G00 Z5.
M05
M30
%
