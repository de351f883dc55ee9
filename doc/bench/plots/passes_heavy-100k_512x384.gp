set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_heavy-100k_512x384.png"
set title "per-pass breakdown: heavy-100k 512x384"
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
"forward-multipass opaque" 0.029365 11.6035 13.0618 36.0906 0 0 0 0 0
"tiled min/max opaque" 0.027192 11.0883 0 0 0.87886 0.145316 39.4395 0 0
"lidr bitshift b4 8-bit backface opaque" 0.092667 9.73339 0 0 0 0 0 12.7443 20.9578
"lidr bitshift b4 8-bit sphere opaque" 0.090812 9.62308 0 0 0 0 0 6.00153 18.432
"lidr bitshift b8 8-bit backface opaque" 0.082085 9.78203 0 0 0 0 0 14.2438 22.2104
"lidr bitshift b8 8-bit sphere opaque" 0.077979 9.7118 0 0 0 0 0 6.79241 19.9307
"lidr auto backface opaque" 0.087977 9.54845 0 0 0 0 0 27.1776 24.1285
"lidr auto sphere opaque" 0.085022 9.53995 0 0 0 0 0 7.05922 19.3549
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
