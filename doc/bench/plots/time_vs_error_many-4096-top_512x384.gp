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
12714.4 0
EOD
$M1 << EOD
30.9045 0.284999
EOD
$M2 << EOD
106.006 4.36908
109.663 1.19135
123.79 0
125.107 0
220.915 0
106.635 4.36908
193.927 1.19135
368.588 0
424.86 0
815.858 0
44.0646 14.4608
43.8284 7.47061
61.4173 6.10259
83.8542 4.74175
106.224 1.48007
EOD
$M3 << EOD
44.9802 0
54.3241 0
EOD
$FRONT << EOD
30.9045 0.284999 "forward-multipass opaque"
44.9802 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
