set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "overlap_error.png"
set terminal pngcairo size 900,520 font 'sans,8' noenhanced
set title "error against overlap k (controlled-overlap scenes)"
set logscale x 2
set yrange [0:*]
set xtics (1,2,4,8,16)
set xrange [0.8:20]
set xlabel 'lights on every lit pixel (k)'
set ylabel "RMSE against forward-brute (8-bit steps)"
set key outside right top font ',7' spacing 0.9
$L0 << EOD
1 0.148043
2 0.179654
4 0
8 0
16 0
EOD
$L1 << EOD
1 0.148043
2 0.179654
4 0.228574
8 0.304918
16 0.431988
EOD
$L2 << EOD
1 0
2 4.11274
4 12.4096
8 25.429
16 40.7118
EOD
$L3 << EOD
1 0
2 4.11274
4 12.4096
8 25.429
16 40.7118
EOD
$L4 << EOD
1 0
2 0
4 0
8 0
16 0.00184142
EOD
$L5 << EOD
1 0
2 0
4 0
8 0
16 0.00184142
EOD
$L6 << EOD
1 0
2 0
4 8.33892
8 21.3765
16 37.1103
EOD
$L7 << EOD
1 0
2 0
4 8.33892
8 21.3765
16 37.1103
EOD
$L8 << EOD
1 0
2 0
4 0
8 13.5515
16 29.9742
EOD
$L9 << EOD
1 0
2 0
4 0
8 13.5515
16 29.9742
EOD
$L10 << EOD
1 0
2 0
4 0
8 0
16 18.2432
EOD
$L11 << EOD
1 0
2 0
4 0
8 0
16 18.2432
EOD
$L12 << EOD
1 0
2 4.11274
4 12.4096
8 25.429
16 40.7118
EOD
$L13 << EOD
1 0
2 4.11274
4 12.4096
8 25.429
16 40.7118
EOD
$L14 << EOD
1 0
2 0
4 0
8 0
16 0.00184142
EOD
$L15 << EOD
1 0
2 0
4 0
8 0
16 0.00184142
EOD
$L16 << EOD
1 0
2 0
4 8.33892
8 21.3765
16 37.1103
EOD
$L17 << EOD
1 0
2 0
4 8.33892
8 21.3765
16 37.1103
EOD
$L18 << EOD
1 0
2 0
4 0
8 13.5515
16 29.9742
EOD
$L19 << EOD
1 0
2 0
4 0
8 13.5515
16 29.9742
EOD
$L20 << EOD
1 0
2 0
4 0
8 0
16 18.2432
EOD
$L21 << EOD
1 0
2 0
4 0
8 0
16 18.2432
EOD
$L22 << EOD
1 0
2 4.11274
4 12.4096
8 25.429
16 40.7118
EOD
$L23 << EOD
1 0
2 4.11274
4 12.4096
8 25.429
16 40.7118
EOD
$L24 << EOD
1 0
2 0
4 0
8 0
16 0.00184142
EOD
$L25 << EOD
1 0
2 0
4 0
8 0
16 0.00184142
EOD
$L26 << EOD
1 0
2 0
4 8.33892
8 21.3765
16 37.1103
EOD
$L27 << EOD
1 0
2 0
4 8.33892
8 21.3765
16 37.1103
EOD
$L28 << EOD
1 0
2 0
4 0
8 13.5515
16 29.9742
EOD
$L29 << EOD
1 0
2 0
4 0
8 13.5515
16 29.9742
EOD
$L30 << EOD
1 0
2 0
4 0
8 0
16 18.2432
EOD
$L31 << EOD
1 0
2 0
4 0
8 0
16 18.2432
EOD
$L32 << EOD
1 0
2 0
4 0
8 0
16 0
EOD
$L33 << EOD
1 0
2 0
4 0
8 0
16 0
EOD
plot $L0 using 1:2 with linespoints pt 7 ps 0.7 title "auto", $L1 using 1:2 with linespoints pt 7 ps 0.7 title "forward-multipass", $L2 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b1 8-bit backface", $L3 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b1 8-bit sphere", $L4 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b16 8-bit backface", $L5 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b16 8-bit sphere", $L6 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b2 8-bit backface", $L7 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b2 8-bit sphere", $L8 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 8-bit backface", $L9 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 8-bit sphere", $L10 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 8-bit backface", $L11 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 8-bit sphere", $L12 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b1 8-bit backface", $L13 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b1 8-bit sphere", $L14 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b16 8-bit backface", $L15 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b16 8-bit sphere", $L16 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b2 8-bit backface", $L17 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b2 8-bit sphere", $L18 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b4 8-bit backface", $L19 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b4 8-bit sphere", $L20 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b8 8-bit backface", $L21 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b8 8-bit sphere", $L22 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b1 8-bit backface", $L23 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b1 8-bit sphere", $L24 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b16 8-bit backface", $L25 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b16 8-bit sphere", $L26 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b2 8-bit backface", $L27 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b2 8-bit sphere", $L28 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b4 8-bit backface", $L29 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b4 8-bit sphere", $L30 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b8 8-bit backface", $L31 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b8 8-bit sphere", $L32 using 1:2 with linespoints pt 7 ps 0.7 title "tiled min/max", $L33 using 1:2 with linespoints pt 7 ps 0.7 title "tiled no-min/max"
