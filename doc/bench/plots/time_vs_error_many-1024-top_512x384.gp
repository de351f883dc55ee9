set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_many-1024-top_512x384.png"
set title "time against error: many-1024-top 512x384 (1024 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
1617.79 0
EOD
$M1 << EOD
27.6122 0.316111
EOD
$M2 << EOD
31.8668 7.22086
39.7429 1.54168
40.6274 0
39.3738 0
63.5182 0
37.821 7.22086
51.6313 1.54168
84.6569 0
139.386 0
259.984 0
23.36 17.6398
31.0512 12.1407
30.7679 10.9258
44.3928 9.10067
63.7394 3.55288
EOD
$M3 << EOD
29.9186 0
34.1521 0
EOD
$FRONT << EOD
23.36 17.6398 "lidr cpu-sorted b1 16-bit backface opaque"
27.6122 0.316111 "forward-multipass opaque"
29.9186 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
