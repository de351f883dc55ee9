set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_many-256-fp_512x384.png"
set title "per-pass breakdown: many-256-fp 512x384"
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
"forward-multipass opaque" 0.035928 6.1358 7.04786 26.3073 0 0 0 0 0
"tiled min/max opaque" 0.021091 5.51284 0 0 0.614979 0.179221 22.5534 0 0
"lidr bitshift b4 16-bit backface opaque" 0.403587 6.06817 0 0 0 0 0 15.682 13.9935
"lidr bitshift b4 16-bit sphere opaque" 0.323744 5.2444 0 0 0 0 0 7.4594 11.9848
"lidr bitshift b8 16-bit backface opaque" 0.385533 5.96808 0 0 0 0 0 16.8399 15.7387
"lidr bitshift b8 16-bit sphere opaque" 0.367227 5.34876 0 0 0 0 0 9.72703 12.4831
"lidr auto backface opaque" 0.073499 5.04574 0 0 0 0 0 27.3242 20.603
"lidr auto sphere opaque" 0.076294 5.19593 0 0 0 0 0 6.50991 10.9486
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
