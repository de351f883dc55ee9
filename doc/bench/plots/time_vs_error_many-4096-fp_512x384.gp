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
5625.91 0
EOD
$M1 << EOD
51.8985 0.180675
EOD
$M2 << EOD
118.543 4.72666
119.311 4.06684
123.488 1.83185
130.22 0.926102
227.513 0.0715554
117.927 4.72666
223.743 4.06684
404.151 1.83185
837.81 0.926102
1592.81 0.0715554
67.8456 8.6353
103.356 6.44049
121.145 5.1546
153.937 4.71179
215.989 4.36498
EOD
$M3 << EOD
134.259 0
188.73 0
EOD
$FRONT << EOD
51.8985 0.180675 "forward-multipass opaque"
134.259 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
