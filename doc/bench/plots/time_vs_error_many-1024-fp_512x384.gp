set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_many-1024-fp_512x384.png"
set title "time against error: many-1024-fp 512x384 (1024 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
2642.32 0
EOD
$M1 << EOD
44.8677 0.210398
EOD
$M2 << EOD
74.8618 5.59226
78.4095 5.34822
89.1501 3.7607
98.4673 1.75436
164.675 0.317794
74.3339 5.59226
164.704 5.34822
241.656 3.7607
463.11 1.75436
896.038 0.317794
49.7662 9.48851
55.1985 7.53729
63.7085 6.82353
80.8445 6.81959
117.134 6.23998
EOD
$M3 << EOD
69.4576 0
89.9704 0
EOD
$FRONT << EOD
44.8677 0.210398 "forward-multipass opaque"
69.4576 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
