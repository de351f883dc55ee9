set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_room_512x384.png"
set title "per-pass breakdown: room 512x384"
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
"forward-multipass opaque" 0.028264 7.61638 7.99161 23.68 0 0 0 0 0
"tiled min/max opaque" 0.025478 6.58522 0 0 0.772818 0.154104 25.4258 0 0
"lidr bitshift b4 8-bit backface opaque" 0.080384 6.04357 0 0 0 0 0 12.8324 13.8743
"lidr bitshift b4 8-bit sphere opaque" 0.067488 6.119 0 0 0 0 0 5.82361 12.3419
"lidr bitshift b8 8-bit backface opaque" 0.066255 6.2586 0 0 0 0 0 13.7178 16.1291
"lidr bitshift b8 8-bit sphere opaque" 0.07351 6.3267 0 0 0 0 0 6.70363 15.6541
"lidr auto backface opaque" 0.074041 6.06238 0 0 0 0 0 26.8343 15.6189
"lidr auto sphere opaque" 0.070895 6.16633 0 0 0 0 0 6.96588 12.5485
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
