set terminal pngcairo size 760,460 font 'sans,8' noenhanced
set grid lc rgb '#dddddd'
set key outside right top
set output "time_vs_error_many-4096-top_512x384.png"
set title "time against error: many-4096-top 512x384 (4096 lights)"
set logscale x
set xlabel 'frame time, ms (median, log scale)'
set ylabel 'RMSE against forward-brute (8-bit steps)'
set yrange [0:*]
$M0 << EOD
22.2397 0
EOD
$M1 << EOD
6028.89 0
EOD
$M2 << EOD
39.7108 0.28319
EOD
$M3 << EOD
22.0641 4.27535
40.3993 4.36908
22.0226 0.761452
43.4332 1.18962
22.5598 0
43.3614 0
25.7308 0
43.9704 0
37.3569 0
62.2078 0
21.8464 4.27535
37.2432 4.36908
26.0698 0.761452
52.7049 1.18962
36.3031 0
89.2696 0
50.043 0
133.296 0
80.7167 0
254.51 0
25.7609 12.6135
25.9367 14.4608
30.0076 2.12001
27.0657 7.47061
30.5045 0
31.5348 5.35901
34.7305 0
39.2414 1.93564
43.184 0
49.268 0
25.49 0
40.5023 0
EOD
$M4 << EOD
41.4165 0
56.1635 0
EOD
$FRONT << EOD
21.8464 4.27535 "lidr max-stencil b1 16-bit sphere opaque"
22.0226 0.761452 "lidr bitshift b2 16-bit sphere opaque"
22.2397 0 "auto opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "auto", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M2 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M3 using 1:2 with points pt 7 ps 1.1 title "lidr", $M4 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
