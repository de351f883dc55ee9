set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_many-4096-top_512x384.png"
set title "time against error: many-4096-top 512x384 (4096 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
6434.51 0
EOD
$M1 << EOD
31.7111 0.28319
EOD
$M2 << EOD
78.4663 4.36908
70.671 1.19135
76.0908 0
82.5792 0
127.868 0
78.1431 4.36908
121.806 1.19135
219.978 0
414.049 0
752.706 0
41.2295 14.4608
44.124 7.47061
62.8066 6.10259
82.7704 4.74175
114.055 1.48007
EOD
$M3 << EOD
42.9507 0
61.4986 0
EOD
$FRONT << EOD
31.7111 0.28319 "forward-multipass opaque"
42.9507 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
