set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_heavy-1m_512x384.png"
set title "time against error: heavy-1m 512x384 (255 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
204.11 0.271534
EOD
$M1 << EOD
131.455 6.4221
114.025 0.00582309
134.217 0.781493
121.166 0
145.381 0
118.329 0
EOD
$M2 << EOD
133.683 0
EOD
$FRONT << EOD
114.025 0.00582309 "lidr bitshift b4 8-bit sphere opaque"
118.329 0 "lidr auto sphere opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M1 using 1:2 with points pt 7 ps 1.1 title "lidr", $M2 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
