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
3166.98 0
EOD
$M1 << EOD
39.6412 0.335316
EOD
$M2 << EOD
48.5143 7.22086
52.9513 1.54168
63.6431 0
64.1974 0
102.724 0
48.4551 7.22086
81.7377 1.54168
142.22 0
253.542 0
484.947 0
37.6968 17.6398
42.4207 12.1407
53.6389 10.9258
74.1122 9.10067
114.195 3.55288
EOD
$M3 << EOD
50.6169 0
60.1732 0
EOD
$FRONT << EOD
37.6968 17.6398 "lidr cpu-sorted b1 16-bit backface opaque"
39.6412 0.335316 "forward-multipass opaque"
50.6169 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
