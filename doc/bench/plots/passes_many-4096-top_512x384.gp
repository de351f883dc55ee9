set terminal pngcairo size 920,520 font 'sans,8' noenhanced
set output "passes_many-4096-top_512x384.png"
set title "per-pass breakdown: many-4096-top 512x384\noff scale: forward-brute opaque 12714 ms"
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
"tiled min/max opaque" 0.057375 4.25206 0.52637 0.533481 39.6661 0 0 0 0
"tiled no-min/max opaque" 0.056644 3.89052 0 0.557968 49.8669 0 0 0 0
"forward-multipass opaque" 0.058877 3.82399 0 0 0 4.76894 22.149 0 0
"lidr bitshift b1 16-bit backface opaque" 0.544127 5.77131 0 0 0 0 0 84.387 15.1706
"lidr bitshift b2 16-bit backface opaque" 0.517117 5.6546 0 0 0 0 0 84.5991 18.7288
"lidr bitshift b4 16-bit backface opaque" 0.552179 5.80556 0 0 0 0 0 89.6314 27.7608
"lidr bitshift b8 16-bit backface opaque" 0.56647 5.84563 0 0 0 0 0 92.675 25.8618
"lidr bitshift b16 16-bit backface opaque" 0.542435 5.76459 0 0 0 0 0 179.749 34.2674
"lidr max-stencil b1 16-bit backface opaque" 0.530286 5.78596 0 0 0 0 0 84.7721 15.2971
"lidr max-stencil b2 16-bit backface opaque" 0.506371 5.77576 0 0 0 0 0 169.181 18.295
"lidr max-stencil b4 16-bit backface opaque" 0.495836 5.73328 0 0 0 0 0 337.301 25.2756
"lidr max-stencil b8 16-bit backface opaque" 0.525519 5.31028 0 0 0 0 0 403.124 15.8998
"lidr max-stencil b16 16-bit backface opaque" 0.529135 3.9688 0 0 0 0 0 793.026 17.9655
"lidr cpu-sorted b1 16-bit backface opaque" 0.47153 3.84658 0 0 0 0 0 28.3129 11.3108
"lidr cpu-sorted b2 16-bit backface opaque" 0.503346 3.87155 0 0 0 0 0 26.0847 13.3014
"lidr cpu-sorted b4 16-bit backface opaque" 0.48595 3.86505 0 0 0 0 0 36.9711 18.2843
"lidr cpu-sorted b8 16-bit backface opaque" 0.499821 3.84829 0 0 0 0 0 50.4345 28.9124
"lidr cpu-sorted b16 16-bit backface opaque" 0.511479 3.82823 0 0 0 0 0 54.7425 47.0593
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
