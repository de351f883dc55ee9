set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_room_320x240.png"
set title "per-pass breakdown: room 320x240\noff scale: forward-brute opaque 195 ms"
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
"tiled min/max opaque" 0.022924 3.90276 0.370981 0.084936 16.3928 0 0 0 0
"forward-multipass opaque" 0.028823 3.6811 0 0 0 4.2272 16.5132 0 0
"lidr bitshift b4 8-bit backface opaque" 0.035653 3.66103 0 0 0 0 0 10.821 9.27492
"lidr bitshift b4 8-bit frontface opaque" 0.038837 3.52393 0 0 0 0 0 9.39069 8.46247
"lidr max-stencil b4 8-bit backface opaque" 0.039829 3.76982 0 0 0 0 0 22.6031 8.89754
"lidr max-stencil b4 8-bit frontface opaque" 0.038788 3.83471 0 0 0 0 0 20.2812 8.83713
"lidr cpu-sorted b4 8-bit backface opaque" 0.041301 3.90646 0 0 0 0 0 4.82806 10.7058
"lidr cpu-sorted b4 8-bit frontface opaque" 0.038918 3.97938 0 0 0 0 0 4.52549 10.4931
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
