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
16.3901 0
EOD
$M1 << EOD
188.45 0
1032.56 0
4087.88 0
EOD
$M2 << EOD
31.5221 0.280794
209.562 0.281397
EOD
$M3 << EOD
25.6745 3.58009
24.5516 7.05133
33.7087 3.58009
35.4934 7.05133
24.3816 18.2709
23.8579 18.2709
36.6503 0
34.7543 0
56.4188 7.00469
70.0099 7.00469
54.1055 18.0904
78.7932 1.08085
117.829 3.43278
137.408 6.78982
150.914 3.43278
154.647 6.78982
120.02 18.0327
130.154 18.0327
184.407 0.0603448
206.36 0.0755765
EOD
$M4 << EOD
24.2707 0
137.732 0
EOD
$FRONT << EOD
16.3901 0 "auto opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "auto", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M2 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M3 using 1:2 with points pt 7 ps 1.1 title "lidr", $M4 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
