set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_many-1024-fp_512x384.png"
set title "time against error: many-1024-fp 512x384 (1024 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
1376.11 0
EOD
$M1 << EOD
38.1638 0.210398
EOD
$M2 << EOD
50.4252 5.59226
55.471 5.34822
68.3645 3.7607
61.3306 1.75436
102.058 0.317794
51.212 5.59226
78.4873 5.34822
136.212 3.7607
236.414 1.75436
484.781 0.317794
31.4926 9.48851
34.3481 7.53729
53.1997 6.82353
60.8588 6.81959
73.5618 6.23998
EOD
$M3 << EOD
37.8132 0
48.1797 0
EOD
$FRONT << EOD
31.4926 9.48851 "lidr cpu-sorted b1 16-bit backface opaque"
34.3481 7.53729 "lidr cpu-sorted b2 16-bit backface opaque"
37.8132 0 "tiled min/max opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M2 using 1:2 with points pt 7 ps 1.1 title "lidr", $M3 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
