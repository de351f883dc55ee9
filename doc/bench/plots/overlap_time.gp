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
1 4.45081
2 5.42276
4 7.83162
8 8.52149
16 14.9927
EOD
$L1 << EOD
1 10.4442
2 20.6924
4 38.2771
8 75.2514
16 137.9
EOD
$L2 << EOD
1 4.30453
2 5.27429
4 7.61031
8 11.6341
16 19.8004
EOD
$L3 << EOD
1 6.68774
2 7.04673
4 8.5851
8 10.213
16 15.8344
EOD
$L4 << EOD
1 6.39623
2 6.27128
4 7.08353
8 7.72797
16 9.59452
EOD
$L5 << EOD
1 8.86714
2 10.3127
4 13.8586
8 19.1972
16 30.8272
EOD
$L6 << EOD
1 7.67441
2 8.56121
4 10.2214
8 11.226
16 18.1061
EOD
$L7 << EOD
1 6.48982
2 7.35788
4 8.99098
8 9.65116
16 16.0034
EOD
$L8 << EOD
1 6.17429
2 6.68858
4 7.08866
8 6.63834
16 9.57512
EOD
$L9 << EOD
1 6.62355
2 7.43349
4 9.71532
8 10.5961
16 16.3719
EOD
$L10 << EOD
1 6.1135
2 6.74689
4 7.54933
8 7.00119
16 9.93042
EOD
$L11 << EOD
1 6.96245
2 7.98408
4 10.1032
8 13.8143
16 18.0443
EOD
$L12 << EOD
1 6.4444
2 6.95616
4 8.21188
8 8.42902
16 11.4722
EOD
$L13 << EOD
1 6.8806
2 7.20708
4 8.28055
8 8.68452
16 10.894
EOD
$L14 << EOD
1 6.72885
2 6.89794
4 7.96559
8 7.15483
16 9.70036
EOD
$L15 << EOD
1 16.415
2 16.8955
4 19.4505
8 20.1354
16 25.6022
EOD
$L16 << EOD
1 16.0868
2 16.8095
4 18.6174
8 19.5308
16 23.1809
EOD
$L17 << EOD
1 7.54592
2 7.94678
4 9.07963
8 8.23893
16 11.8948
EOD
$L18 << EOD
1 7.12521
2 9.44059
4 8.4237
8 8.71061
16 10.4703
EOD
$L19 << EOD
1 8.19592
2 8.75865
4 10.6028
8 11.1748
16 13.4538
EOD
$L20 << EOD
1 8.0419
2 8.75499
4 9.72653
8 9.7696
16 11.7983
EOD
$L21 << EOD
1 10.9085
2 11.1783
4 12.9197
8 14.4787
16 17.7159
EOD
$L22 << EOD
1 10.4108
2 11.3368
4 12.2206
8 12.6722
16 15.7517
EOD
$L23 << EOD
1 6.89415
2 7.60057
4 8.82578
8 9.64305
16 15.8079
EOD
$L24 << EOD
1 6.40322
2 6.70269
4 7.10673
8 6.81576
16 9.73946
EOD
$L25 << EOD
1 14.2072
2 22.6946
4 31.8684
8 46.3838
16 81.5837
EOD
$L26 << EOD
1 11.158
2 14.0683
4 17.5172
8 21.2409
16 38.7607
EOD
$L27 << EOD
1 6.68996
2 7.98068
4 10.0141
8 9.91939
16 16.1603
EOD
$L28 << EOD
1 6.37726
2 6.79048
4 7.39208
8 7.22861
16 11.1639
EOD
$L29 << EOD
1 7.68624
2 9.94762
4 12.5397
8 15.1389
16 30.3544
EOD
$L30 << EOD
1 6.86207
2 8.09689
4 8.94064
8 9.12649
16 13.7031
EOD
$L31 << EOD
1 9.9756
2 12.6014
4 18.4753
8 27.769
16 45.8239
EOD
$L32 << EOD
1 8.32829
2 11.1303
4 11.9963
8 13.7902
16 22.4142
EOD
$L33 << EOD
1 6.89569
2 7.43519
4 8.81275
8 10.4897
16 15.9995
EOD
$L34 << EOD
1 5.87147
2 6.4383
4 7.81866
8 9.54962
16 15.0789
EOD
plot $L0 using 1:2 with linespoints pt 7 ps 0.7 title "auto", $L1 using 1:2 with linespoints pt 7 ps 0.7 title "forward-brute", $L2 using 1:2 with linespoints pt 7 ps 0.7 title "forward-multipass", $L3 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b1 8-bit backface", $L4 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b1 8-bit sphere", $L5 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b16 8-bit backface", $L6 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b16 8-bit sphere", $L7 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b2 8-bit backface", $L8 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b2 8-bit sphere", $L9 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 8-bit backface", $L10 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b4 8-bit sphere", $L11 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 8-bit backface", $L12 using 1:2 with linespoints pt 7 ps 0.7 title "lidr bitshift b8 8-bit sphere", $L13 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b1 8-bit backface", $L14 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b1 8-bit sphere", $L15 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b16 8-bit backface", $L16 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b16 8-bit sphere", $L17 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b2 8-bit backface", $L18 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b2 8-bit sphere", $L19 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b4 8-bit backface", $L20 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b4 8-bit sphere", $L21 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b8 8-bit backface", $L22 using 1:2 with linespoints pt 7 ps 0.7 title "lidr cpu-sorted b8 8-bit sphere", $L23 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b1 8-bit backface", $L24 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b1 8-bit sphere", $L25 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b16 8-bit backface", $L26 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b16 8-bit sphere", $L27 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b2 8-bit backface", $L28 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b2 8-bit sphere", $L29 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b4 8-bit backface", $L30 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b4 8-bit sphere", $L31 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b8 8-bit backface", $L32 using 1:2 with linespoints pt 7 ps 0.7 title "lidr max-stencil b8 8-bit sphere", $L33 using 1:2 with linespoints pt 7 ps 0.7 title "tiled min/max", $L34 using 1:2 with linespoints pt 7 ps 0.7 title "tiled no-min/max"
