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
14.9927 0
EOD
$M1 << EOD
137.9 0
EOD
$M2 << EOD
19.8004 0.431988
EOD
$M3 << EOD
9.59452 40.7118
15.8344 40.7118
9.57512 37.1103
16.0034 37.1103
9.93042 29.9742
16.3719 29.9742
11.4722 18.2432
18.0443 18.2432
18.1061 0.00184142
30.8272 0.00184142
9.73946 40.7118
15.8079 40.7118
11.1639 37.1103
16.1603 37.1103
13.7031 29.9742
30.3544 29.9742
22.4142 18.2432
45.8239 18.2432
38.7607 0.00184142
81.5837 0.00184142
9.70036 40.7118
10.894 40.7118
10.4703 37.1103
11.8948 37.1103
11.7983 29.9742
13.4538 29.9742
15.7517 18.2432
17.7159 18.2432
23.1809 0.00184142
25.6022 0.00184142
18.7043 0.00184142
31.3485 0.00184142
EOD
$M4 << EOD
15.9995 0
15.0789 0
EOD
$FRONT << EOD
9.57512 37.1103 "lidr bitshift b2 8-bit sphere"
9.93042 29.9742 "lidr bitshift b4 8-bit sphere"
11.4722 18.2432 "lidr bitshift b8 8-bit sphere"
14.9927 0 "auto"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "auto", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M2 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M3 using 1:2 with points pt 7 ps 1.1 title "lidr", $M4 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
