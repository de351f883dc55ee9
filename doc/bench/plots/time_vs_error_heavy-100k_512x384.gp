set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_heavy-100k_512x384.png"
set title "time against error: heavy-100k 512x384 (255 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
60.5718 0.27164
EOD
$M1 << EOD
44.022 6.39459
33.8905 0.00701193
49.2616 0.811091
35.8906 0
61.1741 0
36.1393 0
EOD
$M2 << EOD
51.4655 0
EOD
$FRONT << EOD
33.8905 0.00701193 "lidr bitshift b4 8-bit sphere opaque"
35.8906 0 "lidr bitshift b8 8-bit sphere opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M1 using 1:2 with points pt 7 ps 1.1 title "lidr", $M2 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
