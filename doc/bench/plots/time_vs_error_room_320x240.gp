set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_room_320x240.png"
set title "time against error: room 320x240 (255 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
384.199 0
1979.01 0
7766.01 0
EOD
$M1 << EOD
34.0515 0.280794
103.098 0.30117
EOD
$M2 << EOD
35.402 4.16532
33.0759 7.11491
48.5434 4.16532
45.3557 7.11491
28.6798 18.3054
27.8846 18.3054
94.9348 7.06847
102.942 7.06847
100.118 18.121
244.262 4.01997
243.1 6.85609
263.495 4.01997
256.178 6.85609
261.862 18.0634
279.82 18.0634
EOD
$M3 << EOD
36.4678 0
241.973 0
EOD
$FRONT << EOD
27.8846 18.3054 "lidr cpu-sorted b4 8-bit frontface opaque"
33.0759 7.11491 "lidr bitshift b4 8-bit frontface opaque"
34.0515 0.280794 "forward-multipass opaque"
36.4678 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
