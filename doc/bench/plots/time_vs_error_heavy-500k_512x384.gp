set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_heavy-500k_512x384.png"
set title "time against error: heavy-500k 512x384 (255 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
130.476 0.271559
EOD
$M1 << EOD
92.1109 6.42271
92.1193 0.00582309
101.098 0.783085
83.9138 0
125.675 0
80.8322 0
EOD
$M2 << EOD
97.6576 0
EOD
$FRONT << EOD
80.8322 0 "lidr auto sphere opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M1 using 1:2 with points pt 7 ps 1.1 title "lidr", $M2 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
