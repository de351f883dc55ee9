set terminal pngcairo size 950,520 font 'sans,8' noenhanced
set output "passes_overlap-16_512x384.png"
set title "per-pass breakdown: overlap-16 512x384"
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
"forward-brute" 0.028682 0.780227 148.22 0 0 0 0 0 0 0
"tiled min/max" 0.014472 0.954135 0 0.556155 0.069102 13.3601 0 0 0 0
"tiled no-min/max" 0.01315 0.717404 0 0 0.059578 13.3014 0 0 0 0
"forward-multipass" 0.021241 0.731285 0 0 0 0 1.23496 16.2322 0 0
"lidr bitshift b1 8-bit backface" 0.029834 0.711636 0 0 0 0 0 0 9.01354 3.47701
"lidr bitshift b2 8-bit backface" 0.026249 0.711986 0 0 0 0 0 0 9.01902 4.26247
"lidr bitshift b4 8-bit backface" 0.029193 0.732156 0 0 0 0 0 0 9.36438 6.38363
"lidr bitshift b8 8-bit backface" 0.032168 0.708451 0 0 0 0 0 0 10.3044 5.8407
"lidr bitshift b16 8-bit backface" 0.037596 0.730914 0 0 0 0 0 0 21.3715 8.52995
"lidr max-stencil b1 8-bit backface" 0.032227 0.727019 0 0 0 0 0 0 9.19362 3.48724
"lidr max-stencil b2 8-bit backface" 0.035122 0.758695 0 0 0 0 0 0 9.56039 4.39649
"lidr max-stencil b4 8-bit backface" 0.035693 0.72774 0 0 0 0 0 0 18.5571 6.36488
"lidr max-stencil b8 8-bit backface" 0.035844 0.760698 0 0 0 0 0 0 35.455 6.34461
"lidr max-stencil b16 8-bit backface" 0.04061 0.765496 0 0 0 0 0 0 68.8342 8.8974
"lidr cpu-sorted b1 8-bit backface" 0.034742 0.742021 0 0 0 0 0 0 6.03828 8.57675
"lidr cpu-sorted b2 8-bit backface" 0.036334 0.760929 0 0 0 0 0 0 4.45183 6.20064
"lidr cpu-sorted b4 8-bit backface" 0.036093 0.747438 0 0 0 0 0 0 4.6166 8.56492
"lidr cpu-sorted b8 8-bit backface" 0.042823 1.14367 0 0 0 0 0 0 5.91843 14.1556
"lidr cpu-sorted b16 8-bit backface" 0.042563 0.771159 0 0 0 0 0 0 6.79801 26.4051
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "brute-force", $P using 5 title "tile-depth-reduce", $P using 6 title "light-grid", $P using 7 title "tiled-forward", $P using 8 title "ambient", $P using 9 title "light-passes", $P using 10 title "light-volumes", $P using 11 title "forward"
