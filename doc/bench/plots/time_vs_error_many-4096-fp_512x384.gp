set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_many-4096-fp_512x384.png"
set title "time against error: many-4096-fp 512x384 (4096 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
22.5993 0
EOD
$M1 << EOD
4827.73 0
EOD
$M2 << EOD
43.5089 0.180675
EOD
$M3 << EOD
22.5573 2.87297
51.704 4.57237
22.535 1.74499
49.6153 3.80623
28.2427 0
50.5583 0.746281
25.2437 0
53.2719 0.119487
32.984 0
79.0405 0
24.5439 2.87297
49.0436 4.57237
25.136 1.74499
75.2659 3.80623
34.1432 0
113.821 0.746281
51.9936 0
187.14 0.119487
75.0124 0
352.438 0
31.4749 6.38059
32.4462 8.63518
34.7143 2.53335
33.4708 5.66464
38.2676 0
37.254 4.49934
41.8212 0
44.6804 2.18424
52.1184 0
57.4916 0.368697
22.4005 0
83.8667 0
EOD
$M4 << EOD
72.1473 0
95.9297 0
EOD
$FRONT << EOD
22.4005 0 "lidr auto sphere opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "auto", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M2 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M3 using 1:2 with points pt 7 ps 1.1 title "lidr", $M4 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
