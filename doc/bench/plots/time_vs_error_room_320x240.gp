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
195.341 0
1044.5 0
4139.14 0
EOD
$M1 << EOD
24.435 0.280794
183.389 0.281397
EOD
$M2 << EOD
23.8191 4.16532
21.4136 7.11491
36.2885 4.16532
33.2224 7.11491
19.663 18.3054
19.019 18.3054
52.8757 7.06847
59.9631 7.06847
54.7125 18.121
125.222 4.01997
122.23 6.85609
139.79 4.01997
135.247 6.85609
142.53 18.0634
142.617 18.0634
EOD
$M3 << EOD
20.8228 0
127.199 0
EOD
$FRONT << EOD
19.019 18.3054 "lidr cpu-sorted b4 8-bit frontface opaque"
20.8228 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
