set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_many-16384-fp_512x384.png"
set title "per-pass breakdown: many-16384-fp 512x384"
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
"forward-multipass opaque" 0.131599 5.19914 6.91138 59.6418 0 0 0 0 0
"tiled min/max opaque" 0.128615 5.40773 0 0 0.680974 2.12593 204.239 0 0
"lidr bitshift b4 16-bit backface opaque" 4.11398 8.42771 0 0 0 0 0 47.8676 16.8151
"lidr bitshift b4 16-bit sphere opaque" 4.18314 5.3521 0 0 0 0 0 5.64724 10.7501
"lidr bitshift b8 16-bit backface opaque" 3.99426 5.3284 0 0 0 0 0 57.8639 16.7093
"lidr bitshift b8 16-bit sphere opaque" 4.09446 5.42947 0 0 0 0 0 6.85547 10.9459
"lidr auto backface opaque" 3.85447 4.78087 0 0 0 0 0 93.9931 26.1731
"lidr auto sphere opaque" 3.84308 5.12826 0 0 0 0 0 5.88106 10.6195
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
