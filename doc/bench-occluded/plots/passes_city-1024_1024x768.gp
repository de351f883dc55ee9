set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_city-1024_1024x768.png"
set title "per-pass breakdown: city-1024 1024x768\noff scale: forward-multipass opaque 1076 ms"
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
"tiled min/max opaque" 0.027852 14.1088 3.30969 0.261332 47.3872 0 0 0 0
"auto opaque" 0.626251 12.3744 0 0 0 5.74425 6.5363 2.80255 41.4764
"lidr auto sphere opaque" 0.662004 20.0131 0 0 0 5.73191 10.2187 2.88021 55.6
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "volume-tiles", $P using 8 title "light-volumes", $P using 9 title "overlap-probe", $P using 10 title "forward"
