set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "lights_time.png"
set terminal pngcairo size 900,520 font 'sans,8' noenhanced
set title "frame time against light count (many-N-fp scenes)"
set logscale x 2
set logscale y
set xlabel "lights in the scene (log scale)"
set ylabel "frame time, ms (median over rounds, log scale)"
set key outside right top font ',7' spacing 0.9
$S0 << EOD
64 39.603
256 39.8711
1024 37.8739
4096 43.5089
16384 72.9315
EOD
$S1 << EOD
64 30.0078
256 36.2413
1024 40.4762
4096 50.5583
16384 75.9725
EOD
$S2 << EOD
64 25.2314
256 25.7132
1024 24.0687
4096 28.2427
16384 26.5535
EOD
$S3 << EOD
64 28.9537
256 40.4951
1024 46.6094
4096 53.2719
16384 82.7794
EOD
$S4 << EOD
64 26.9644
256 28.7495
1024 25.6904
4096 25.2437
16384 26.8686
EOD
$S5 << EOD
64 27.1519
256 28.8401
1024 42.326
4096 72.1473
16384 215.337
EOD
plot $S0 using 1:2 with linespoints pt 7 ps 0.7 title "forward-multipass", $S1 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 backface", $S2 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 sphere", $S3 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 backface", $S4 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 sphere", $S5 using 1:2 with linespoints pt 7 ps 0.7 title "tiled min/max"
