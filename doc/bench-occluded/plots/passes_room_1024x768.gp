set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_room_1024x768.png"
set title "per-pass breakdown: room 1024x768"
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
"forward-multipass opaque" 0.028263 9.19064 18.8817 62.184 0 0 0 0 0 0 0
"tiled min/max opaque" 0.023775 11.2365 0 0 3.6129 0.240561 106.815 0 0 0 0
"auto opaque" 0.027441 9.46839 18.8727 60.7363 0 0 0 0 0 0 0
"lidr auto sphere opaque" 0.997458 9.59287 0 0 0 0 0 9.16628 14.2808 2.49547 52.0435
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "volume-tiles", $P using 10 title "light-volumes", $P using 11 title "overlap-probe", $P using 12 title "forward"
