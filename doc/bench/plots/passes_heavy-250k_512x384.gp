set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_heavy-250k_512x384.png"
set title "per-pass breakdown: heavy-250k 512x384"
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
"forward-multipass opaque" 0.049374 23.5841 29.1718 58.9674 0 0 0 0 0
"tiled min/max opaque" 0.028574 26.8918 0 0 0.992044 0.158741 57.2186 0 0
"lidr bitshift b4 8-bit backface opaque" 0.111361 25.2436 0 0 0 0 0 17.4058 39.9262
"lidr bitshift b4 8-bit sphere opaque" 0.13206 25.2211 0 0 0 0 0 7.40831 37.4882
"lidr bitshift b8 8-bit backface opaque" 0.107273 23.3276 0 0 0 0 0 18.5288 38.1772
"lidr bitshift b8 8-bit sphere opaque" 0.111572 23.0716 0 0 0 0 0 8.38892 36.5663
"lidr auto backface opaque" 0.124808 22.8808 0 0 0 0 0 30.2498 40.2234
"lidr auto sphere opaque" 0.127331 19.3763 0 0 0 0 0 8.46845 31.3718
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
