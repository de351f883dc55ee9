set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_hall-255_1024x768.png"
set title "per-pass breakdown: hall-255 1024x768\noff scale: forward-multipass opaque 2499 ms"
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
"tiled min/max opaque" 0.025368 32.1065 6.78916 0.280461 175.708 0 0 0 0
"auto opaque" 1.54934 31.7828 0 0 0 9.82883 21.2179 3.90608 103.106
"lidr auto sphere opaque" 1.98298 47.2848 0 0 0 9.86359 23.1649 3.13996 112.676
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "volume-tiles", $P using 8 title "light-volumes", $P using 9 title "overlap-probe", $P using 10 title "forward"
