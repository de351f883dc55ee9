set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_many-64-fp_512x384.png"
set title "per-pass breakdown: many-64-fp 512x384"
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
"forward-multipass opaque" 0.031349 8.39414 6.59643 25.6557 0 0 0 0 0
"tiled min/max opaque" 0.021741 5.55776 0 0 0.696112 0.115831 20.4067 0 0
"lidr bitshift b4 8-bit backface opaque" 0.039355 5.85554 0 0 0 0 0 8.91702 14.0217
"lidr bitshift b4 8-bit sphere opaque" 0.039204 5.79795 0 0 0 0 0 7.38583 11.996
"lidr bitshift b8 8-bit backface opaque" 0.034476 5.11497 0 0 0 0 0 9.34444 14.5642
"lidr bitshift b8 8-bit sphere opaque" 0.037261 5.14183 0 0 0 0 0 8.46351 13.3363
"lidr auto backface opaque" 0.04263 4.99549 0 0 0 0 0 16.7476 15.6243
"lidr auto sphere opaque" 0.043764 5.35713 0 0 0 0 0 8.78715 12.6419
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
