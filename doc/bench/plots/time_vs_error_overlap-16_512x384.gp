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
149.025 0
EOD
$M1 << EOD
18.1483 0.431988
EOD
$M2 << EOD
13.3167 40.7118
13.9565 37.1103
16.5121 29.9742
16.9143 18.2432
30.6686 0.00184142
13.4408 40.7118
14.7328 37.1103
25.719 29.9742
42.5986 18.2432
79.086 0.00184142
15.5462 40.7118
11.3925 37.1103
13.9862 29.9742
21.2639 18.2432
33.9307 0.00184142
EOD
$M3 << EOD
15.0823 0
14.0794 0
EOD
$FRONT << EOD
11.3925 37.1103 "lidr cpu-sorted b2 8-bit backface"
13.9862 29.9742 "lidr cpu-sorted b4 8-bit backface"
14.0794 0 "tiled no-min/max"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
