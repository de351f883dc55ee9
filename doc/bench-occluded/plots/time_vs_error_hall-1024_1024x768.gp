set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_hall-1024_1024x768.png"
set title "time against error: hall-1024 1024x768 (1024 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
434.415 0.00112764
EOD
$M1 << EOD
5798.01 0.544808
EOD
$M2 << EOD
383.031 0.00112764
1227.35 0.00112764
EOD
$M3 << EOD
591.728 0
EOD
$FRONT << EOD
383.031 0.00112764 "lidr auto sphere opaque"
591.728 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "auto", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
