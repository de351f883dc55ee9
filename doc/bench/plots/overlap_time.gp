set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set terminal pngcairo size 900,520 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "overlap_time.png"
set title "frame time against overlap k (controlled-overlap scenes)"
set logscale x 2
set logscale y 2
set xtics (1,2,4,8,16)
set xrange [0.8:20]
set xlabel 'lights on every lit pixel (k)'
set ylabel "frame time, ms (median, log scale)"
set key outside right top font ',7' spacing 0.9
$L0 << EOD
1 19.7903
2 42.4919
4 79.9558
8 148.965
16 293.745
EOD
$L1 << EOD
1 4.42288
2 5.97099
4 8.84297
8 15.612
16 27.0212
EOD
$L2 << EOD
1 8.61675
2 9.64536
4 11.1951
8 14.8283
16 21.0121
EOD
$L3 << EOD
1 14.591
2 16.9455
4 21.5088
8 30.5787
16 49.7151
EOD
$L4 << EOD
1 10.4138
2 11.2948
4 13.5271
8 16.528
16 23.9432
EOD
$L5 << EOD
1 14.5125
2 15.6178
4 17.9347
8 21.091
16 27.9062
EOD
$L6 << EOD
1 11.1408
2 12.9569
4 16.0834
8 21.1934
16 29.0255
EOD
$L7 << EOD
1 11.3376
2 11.7111
4 18.7419
8 13.5259
16 16.871
EOD
$L8 << EOD
1 54.7352
2 55.9984
4 56.0171
8 59.1617
16 68.4255
EOD
$L9 << EOD
1 13.9651
2 19.3739
4 15.0542
8 16.0856
16 19.4031
EOD
$L10 << EOD
1 18.8824
2 16.214
4 20.1785
8 21.4796
16 24.9407
EOD
$L11 << EOD
1 30.093
2 30.6328
4 31.8382
8 33.8616
16 37.2715
EOD
$L12 << EOD
1 8.36714
2 9.87764
4 11.072
8 17.171
16 21.1031
EOD
$L13 << EOD
1 20.5812
2 29.0454
4 42.3663
8 70.6056
16 134.201
EOD
$L14 << EOD
1 10.1909
2 11.8284
4 13.1486
8 15.7089
16 23.5394
EOD
$L15 << EOD
1 14.6149
2 17.251
4 20.596
8 26.626
16 42.0651
EOD
$L16 << EOD
1 14.0216
2 19.4478
4 26.4494
8 41.4303
16 71.051
EOD
$L17 << EOD
1 10.1861
2 11.2516
4 13.7892
8 18.9738
16 32.5867
EOD
$L18 << EOD
1 8.97571
2 10.3044
4 12.6882
8 18.6624
16 28.0958
EOD
plot $L0 using 1:2 with linespoints pt 7 ps 0.7 title "forward-brute", $L1 using 1:2 with linespoints pt 7 ps 0.7 title "forward-multipass", $L2 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b1 8-bit backface", $L3 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b16 8-bit backface", $L4 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b2 8-bit backface", $L5 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 8-bit backface", $L6 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 8-bit backface", $L7 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b1 8-bit backface", $L8 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b16 8-bit backface", $L9 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b2 8-bit backface", $L10 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b4 8-bit backface", $L11 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b8 8-bit backface", $L12 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b1 8-bit backface", $L13 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b16 8-bit backface", $L14 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b2 8-bit backface", $L15 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b4 8-bit backface", $L16 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b8 8-bit backface", $L17 using 1:2 with linespoints pt 7 ps 0.7 title "tiled min/max", $L18 using 1:2 with linespoints pt 7 ps 0.7 title "tiled no-min/max"
