%
O4711 (BEZCAM)
N10 (bezcam 0.1.0: job-two-tools.json, machine fanuc, output nurbs)
N20 (tolerance 0.01 mm; largest deviation measured below 1e-05 mm, proven bound 0 mm, rounding included)
N30 (T1: pocket-outline)
N40 (T2: engraving)
N50 (estimated cycle time 16 s: feeds as programmed, rapids at 15000 mm/min, no acceleration, tool changes not counted)
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S10000 M03
N130 M08
N140 (entity pocket-outline: path, degree 3, 2D)
N150 G00 Z5.
N160 X0. Y0.
N170 Z1.
N180 G01 Z-1. F250.
N190 X40. F900.
N200 G06.2 P4 K0. X40. Y0. Z-1. R1.
N210 K0. X55. Y0. Z-1. R1.
N220 K0. X55. Y25. Z-1. R1.
N230 K0. X40. Y25. Z-1. R1.
N240 K1.
N250 K1.
N260 K1.
N270 K1.
N280 G01 X0.
N290 G06.2 P4 K0. X0. Y25. Z-1. R1.
N300 K0. X-15. Y25. Z-1. R1.
N310 K0. X-15. Y0. Z-1. R1.
N320 K0. X0. Y0. Z-1. R1.
N330 K1.
N340 K1.
N350 K1.
N360 K1.
N370 G00 Z5.
N380 M09
N390 M05
N400 G53 G00 Z0.
N410 T2 M06
N420 G43 H2
N430 S18000 M03
N440 M07
N450 (entity engraving: bezier, degree 3, 2D)
N460 G00 Z5.
N470 X5. Y12.5
N480 Z1.
N490 G01 Z-0.2 F250.
N500 G06.2 P4 K0. X5. Y12.5 Z-0.2 R1. F400.
N510 K0. X15. Y22. Z-0.2 R1.
N520 K0. X25. Y3. Z-0.2 R1.
N530 K0. X35. Y12.5 Z-0.2 R1.
N540 K1.
N550 K1.
N560 K1.
N570 K1.
N580 G00 Z5.
N590 M09
N600 M05
N610 M30
%
