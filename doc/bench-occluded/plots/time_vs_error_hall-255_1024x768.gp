set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_hall-255_1024x768.png"
set title "time against error: hall-255 1024x768 (255 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
166.38 0
EOD
$M1 << EOD
2499.24 0.385078
EOD
$M2 << EOD
202.363 0
297.491 0
EOD
$M3 << EOD
217.229 0
EOD
$FRONT << EOD
166.38 0 "auto opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "auto", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
