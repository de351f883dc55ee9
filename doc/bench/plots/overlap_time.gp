set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "overlap_time.png"
set terminal pngcairo size 900,520 font 'sans,8' noenhanced
set title "frame time against overlap k (controlled-overlap scenes)"
set logscale x 2
set logscale y 2
set xtics (1,2,4,8,16)
set xrange [0.8:20]
set xlabel 'lights on every lit pixel (k)'
set ylabel "frame time, ms (median, log scale)"
set key outside right top font ',7' spacing 0.9
$L0 << EOD
1 10.1379
2 21.5725
4 40.8181
8 76.5182
16 149.025
EOD
$L1 << EOD
1 2.98475
2 5.36305
4 6.07692
8 10.0115
16 18.1483
EOD
$L2 << EOD
1 4.95351
2 5.32074
4 9.49479
8 8.81629
16 13.3167
EOD
$L3 << EOD
1 8.27408
2 12.2903
4 13.1341
8 18.7447
16 30.6686
EOD
$L4 << EOD
1 5.78418
2 6.29119
4 13.6491
8 9.60758
16 13.9565
EOD
$L5 << EOD
1 7.93937
2 8.4894
4 12.0416
8 12.0481
16 16.5121
EOD
$L6 << EOD
1 6.07676
2 9.3852
4 8.92325
8 12.2401
16 16.9143
EOD
$L7 << EOD
1 6.15268
2 6.35761
4 6.75129
8 7.73879
16 15.5462
EOD
$L8 << EOD
1 27.8537
2 31.8932
4 28.9684
8 30.4606
16 33.9307
EOD
$L9 << EOD
1 7.40549
2 9.75782
4 8.22992
8 9.14935
16 11.3925
EOD
$L10 << EOD
1 9.75052
2 11.7924
4 10.7513
8 11.8235
16 13.9862
EOD
$L11 << EOD
1 15.5109
2 17.5212
4 16.4191
8 17.952
16 21.2639
EOD
$L12 << EOD
1 4.84478
2 7.30488
4 6.44675
8 8.93567
16 13.4408
EOD
$L13 << EOD
1 12.4597
2 21.6147
4 26.2096
8 44.2513
16 79.086
EOD
$L14 << EOD
1 6.58068
2 9.22063
4 7.45751
8 10.0592
16 14.7328
EOD
$L15 << EOD
1 8.21111
2 13.5344
4 11.3379
8 16.2904
16 25.719
EOD
$L16 << EOD
1 8.34662
2 13.7964
4 16.3095
8 26.6281
16 42.5986
EOD
$L17 << EOD
1 5.47056
2 7.56476
4 7.26505
8 10.2416
16 15.0823
EOD
$L18 << EOD
1 4.83707
2 6.70751
4 6.72703
8 9.15007
16 14.0794
EOD
plot $L0 using 1:2 with linespoints pt 7 ps 0.7 title "forward-brute", $L1 using 1:2 with linespoints pt 7 ps 0.7 title "forward-multipass", $L2 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b1 8-bit backface", $L3 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b16 8-bit backface", $L4 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b2 8-bit backface", $L5 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 8-bit backface", $L6 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 8-bit backface", $L7 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b1 8-bit backface", $L8 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b16 8-bit backface", $L9 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b2 8-bit backface", $L10 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b4 8-bit backface", $L11 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b8 8-bit backface", $L12 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b1 8-bit backface", $L13 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b16 8-bit backface", $L14 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b2 8-bit backface", $L15 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b4 8-bit backface", $L16 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b8 8-bit backface", $L17 using 1:2 with linespoints pt 7 ps 0.7 title "tiled min/max", $L18 using 1:2 with linespoints pt 7 ps 0.7 title "tiled no-min/max"
