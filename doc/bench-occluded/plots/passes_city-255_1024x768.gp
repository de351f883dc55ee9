set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_city-255_1024x768.png"
set title "per-pass breakdown: city-255 1024x768"
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
"forward-multipass opaque" 0.025118 15.0209 31.4212 251.943 0 0 0 0 0 0 0
"tiled min/max opaque" 0.022955 27.7023 0 0 7.46044 0.114722 68.1536 0 0 0 0
"auto opaque" 0.233761 24.102 0 0 0 0 0 9.23668 2.70996 3.33882 63.6317
"lidr auto sphere opaque" 0.241693 19.1878 0 0 0 0 0 12.958 2.60536 5.25562 63.2438
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "volume-tiles", $P using 10 title "light-volumes", $P using 11 title "overlap-probe", $P using 12 title "forward"
