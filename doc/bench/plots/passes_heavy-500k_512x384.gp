set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_heavy-500k_512x384.png"
set title "per-pass breakdown: heavy-500k 512x384"
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
"forward-multipass opaque" 0.034637 33.7751 34.3599 66.7778 0 0 0 0 0
"tiled min/max opaque" 0.027132 31.4987 0 0 0.981805 0.212113 69.3922 0 0
"lidr bitshift b4 8-bit backface opaque" 0.118084 29.2363 0 0 0 0 0 16.9899 46.3351
"lidr bitshift b4 8-bit sphere opaque" 0.098557 38.7514 0 0 0 0 0 6.9894 46.2818
"lidr bitshift b8 8-bit backface opaque" 0.121801 35.7823 0 0 0 0 0 19.1594 49.654
"lidr bitshift b8 8-bit sphere opaque" 0.101823 33.9129 0 0 0 0 0 8.19469 44.6026
"lidr auto backface opaque" 0.101653 32.9178 0 0 0 0 0 34.8362 51.7831
"lidr auto sphere opaque" 0.093357 29.2044 0 0 0 0 0 8.17206 40.7307
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
