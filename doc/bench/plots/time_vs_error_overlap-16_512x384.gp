set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_overlap-16_512x384.png"
set title "time against error: overlap-16 512x384 (144 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
293.745 0
EOD
$M1 << EOD
27.0212 0.431988
EOD
$M2 << EOD
21.0121 40.7118
23.9432 37.1103
27.9062 29.9742
29.0255 18.2432
49.7151 0.00184142
21.1031 40.7118
23.5394 37.1103
42.0651 29.9742
71.051 18.2432
134.201 0.00184142
16.871 40.7118
19.4031 37.1103
24.9407 29.9742
37.2715 18.2432
68.4255 0.00184142
EOD
$M3 << EOD
32.5867 0
28.0958 0
EOD
$FRONT << EOD
16.871 40.7118 "lidr cpu-sorted b1 8-bit backface"
19.4031 37.1103 "lidr cpu-sorted b2 8-bit backface"
24.9407 29.9742 "lidr cpu-sorted b4 8-bit backface"
27.0212 0.431988 "forward-multipass"
28.0958 0 "tiled no-min/max"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
