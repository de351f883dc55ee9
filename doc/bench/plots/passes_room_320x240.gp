set terminal pngcairo size 720,520 font 'sans,8' noenhanced
set output "passes_room_320x240.png"
set title "per-pass breakdown: room 320x240\noff scale: forward-brute opaque 384 ms"
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
"tiled min/max opaque" 0.024607 5.63766 0.476537 0.084626 30.1489 0 0 0 0
"forward-multipass opaque" 0.028262 5.08622 0 0 0 6.01966 22.894 0 0
"lidr bitshift b4 8-bit backface opaque" 0.049743 5.21541 0 0 0 0 0 15.4698 14.744
"lidr bitshift b4 8-bit frontface opaque" 0.044987 5.01827 0 0 0 0 0 13.5178 14.285
"lidr max-stencil b4 8-bit backface opaque" 0.042302 5.05455 0 0 0 0 0 29.5405 14.163
"lidr max-stencil b4 8-bit frontface opaque" 0.039559 4.99098 0 0 0 0 0 26.5473 13.7747
"lidr cpu-sorted b4 8-bit backface opaque" 0.042553 5.03586 0 0 0 0 0 6.31551 17.2664
"lidr cpu-sorted b4 8-bit frontface opaque" 0.046389 4.98036 0 0 0 0 0 5.76028 17.0752
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
