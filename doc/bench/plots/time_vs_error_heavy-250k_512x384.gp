set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_heavy-250k_512x384.png"
set title "time against error: heavy-250k 512x384 (255 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
114.477 0.271159
EOD
$M1 << EOD
83.2837 6.41149
71.747 0.00582309
87.1255 0.78584
66.8887 0
95.3647 0
59.2983 0
EOD
$M2 << EOD
85.2044 0
EOD
$FRONT << EOD
59.2983 0 "lidr auto sphere opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M1 using 1:2 with points pt 7 ps 1.1 title "lidr", $M2 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
