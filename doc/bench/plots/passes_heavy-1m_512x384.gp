set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_heavy-1m_512x384.png"
set title "per-pass breakdown: heavy-1m 512x384"
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
"forward-multipass opaque" 0.024798 46.7703 57.8521 95.7094 0 0 0 0 0
"tiled min/max opaque" 0.025638 44.8609 0 0 0.839746 0.187656 87.0777 0 0
"lidr bitshift b4 8-bit backface opaque" 0.096975 47.2561 0 0 0 0 0 15.0501 70.2892
"lidr bitshift b4 8-bit sphere opaque" 0.086784 44.9377 0 0 0 0 0 10.273 59.6573
"lidr bitshift b8 8-bit backface opaque" 0.082877 45.4835 0 0 0 0 0 18.7323 67.8236
"lidr bitshift b8 8-bit sphere opaque" 0.091723 47.0439 0 0 0 0 0 7.93839 68.7815
"lidr auto backface opaque" 0.108876 48.6239 0 0 0 0 0 30.0834 69.6593
"lidr auto sphere opaque" 0.1105 43.9909 0 0 0 0 0 7.4911 67.3943
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
