set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_hall-1024_1024x768.png"
set title "per-pass breakdown: hall-1024 1024x768\noff scale: forward-multipass opaque 5798 ms"
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
"tiled min/max opaque" 0.029975 35.5499 3.44172 0.518809 553.721 0 0 0 0
"auto opaque" 4.81019 24.114 0 0 0 6.04763 172.064 9.31556 204.001
"lidr auto sphere opaque" 4.67026 37.6938 0 0 0 10.0658 144.861 5.40614 203.853
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "volume-tiles", $P using 8 title "light-volumes", $P using 9 title "overlap-probe", $P using 10 title "forward"
