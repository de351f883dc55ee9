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
23.2708 0
EOD
$M1 << EOD
1282.4 0
EOD
$M2 << EOD
37.8739 0.210398
EOD
$M3 << EOD
22.4379 2.38379
39.6306 5.51496
22.7657 0.672306
37.8435 4.92207
24.0687 0
40.4762 3.53402
25.6904 0
46.6094 1.71671
38.7042 0
63.5699 0
22.9679 2.38379
39.0105 5.51496
26.6684 0.672306
54.7155 4.92207
35.1028 0
93.379 3.53402
52.8305 0
152.967 1.71671
81.6304 0
267.383 0
24.6466 8.12828
33.0336 9.48851
26.0615 4.67534
28.8759 7.53723
30.3006 0.881981
32.3868 6.82809
32.8402 0
37.0324 6.34146
40.6011 0
46.1269 5.5677
23.098 0
64.9577 0
EOD
$M4 << EOD
42.326 0
50.6965 0
EOD
$FRONT << EOD
22.4379 2.38379 "lidr bitshift b1 16-bit sphere opaque"
22.7657 0.672306 "lidr bitshift b2 16-bit sphere opaque"
23.098 0 "lidr auto sphere opaque"
EOD
plot $M0 using 1:2 with points pt 7 ps 1.1 title "auto", $M1 using 1:2 with points pt 7 ps 1.1 title "forward-brute", $M2 using 1:2 with points pt 7 ps 1.1 title "forward-multipass", $M3 using 1:2 with points pt 7 ps 1.1 title "lidr", $M4 using 1:2 with points pt 7 ps 1.1 title "tiled", $FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', $FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle
