set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "triangles_time.png"
set terminal pngcairo size 900,520 font 'sans,8' noenhanced
set title "frame time against scene triangles (room, heavy-T scenes; 255 lights)"
set logscale x 2
set yrange [0:*]
set xlabel "triangles in the scene (log scale)"
set ylabel "frame time, ms (median over rounds)"
set key outside right top font ',7' spacing 0.9
$S0 << EOD
40272 42.2219
95568 60.5718
249168 114.477
464208 130.476
954192 204.11
EOD
$S2 << EOD
40272 32.2078
95568 44.022
249168 83.2837
464208 92.1109
954192 131.455
EOD
$S6 << EOD
40272 24.3513
95568 33.8905
249168 71.747
464208 92.1193
954192 114.025
EOD
$S8 << EOD
40272 34.6815
95568 49.2616
249168 87.1255
464208 101.098
954192 134.217
EOD
$S12 << EOD
40272 29.6885
95568 35.8906
249168 66.8887
464208 83.9138
954192 121.166
EOD
$S13 << EOD
40272 33.6946
95568 51.4655
249168 85.2044
464208 97.6576
954192 133.683
EOD
plot $S0 using 1:2 with linespoints pt 7 ps 0.7 title "forward-multipass 512x384", $S2 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 backface 512x384", $S6 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 sphere 512x384", $S8 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 backface 512x384", $S12 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 sphere 512x384", $S13 using 1:2 with linespoints pt 7 ps 0.7 title "tiled min/max 512x384"
