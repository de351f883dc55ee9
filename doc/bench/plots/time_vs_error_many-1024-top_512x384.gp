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
20.9847 0
EOD
$M1 << EOD
1479.91 0
EOD
$M2 << EOD
31.3072 0.316111
EOD
$M3 << EOD
20.4713 6.77043
28.1469 7.22086
21.9191 0.667552
28.6163 1.54168
22.2244 0
30.1585 0
30.0322 0
33.1928 0
33.1388 0
43.4418 0
21.1879 6.77043
27.9287 7.22086
25.1857 0.667552
41.4963 1.54168
34.2166 0
59.8159 0
49.0012 0
95.851 0
84.6987 0
178.254 0
21.5591 14.9634
22.4933 17.6398
23.0476 6.18541
23.4855 12.1407
29.6788 1.0591
27.2339 10.5121
29.7744 0
31.7539 6.54039
38.721 0
42.3886 0
20.8308 0
32.567 0
EOD
$M4 << EOD
30.4682 0
34.9261 0
EOD
$FRONT << EOD
20.4713 6.77043 "lidr bitshift b1 16-bit sphere opaque"
20.8308 0 "lidr auto sphere opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "auto", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M2 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M3 using 1:2 with points pt 7 ps 1.1 title "lidr", $M4 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
