set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_room_320x240.png"
set title "per-pass breakdown: room 320x240\noff scale: forward-brute opaque 188 ms"
set style data histograms
set style histogram rowstacked
set style fill solid 0.85 border -1
set boxwidth 0.75
set xtics rotate by -40 left font ',7'
set ylabel 'ms (median per pass)'
set key outside right top
set grid ytics lc rgb '#dddddd'
set yrange [0:*]
set bmargin 12
$P << EOD
"forward-multipass opaque" 0.042651 4.69931 6.0363 19.3413 0 0 0 0 0
"tiled min/max opaque" 0.026771 5.14508 0 0 0.501303 0.143071 18.211 0 0
"auto opaque" 0.078369 4.9181 0 0 0 0 0 3.04304 8.35219
"lidr bitshift b4 8-bit backface opaque" 0.083309 5.19417 0 0 0 0 0 9.96751 9.53391
"lidr bitshift b4 8-bit frontface opaque" 0.074541 5.49519 0 0 0 0 0 9.42047 9.65857
"lidr max-stencil b4 8-bit backface opaque" 0.073108 4.86538 0 0 0 0 0 19.3136 9.41849
"lidr max-stencil b4 8-bit frontface opaque" 0.083789 5.13737 0 0 0 0 0 18.4458 10.8042
"lidr cpu-sorted b4 8-bit backface opaque" 0.092476 5.03003 0 0 0 0 0 5.28764 11.4243
"lidr cpu-sorted b4 8-bit frontface opaque" 0.063751 6.20993 0 0 0 0 0 6.16045 11.2664
"lidr auto backface opaque" 0.07406 4.99944 0 0 0 0 0 19.7475 9.96738
"lidr auto frontface opaque" 0.084941 4.60128 0 0 0 0 0 18.1052 11.4697
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
