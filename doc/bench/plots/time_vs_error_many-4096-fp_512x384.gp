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
5486.86 0
EOD
$M1 << EOD
37.9044 0.180675
EOD
$M2 << EOD
139.377 4.72666
129.275 4.06684
116.394 1.83185
128.961 0.926102
226.523 0.0715554
118.406 4.72666
209.986 4.06684
384.656 1.83185
734.557 0.926102
1442.84 0.0715554
66.1117 8.6353
69.0475 6.44049
83.8444 5.1546
106.899 4.71179
154.9 4.36498
EOD
$M3 << EOD
74.0133 0
97.3892 0
EOD
$FRONT << EOD
37.9044 0.180675 "forward-multipass opaque"
74.0133 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
