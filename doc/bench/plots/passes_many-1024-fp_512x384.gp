set terminal pngcairo size 950,520 font 'sans,8' noenhanced
set output "passes_many-1024-fp_512x384.png"
set title "per-pass breakdown: many-1024-fp 512x384"
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
"forward-brute opaque" 0.044316 9.65309 2632.62 0 0 0 0 0 0 0
"tiled min/max opaque" 0.039198 7.67252 0 0.899704 0.219646 60.6117 0 0 0 0
"tiled no-min/max opaque" 0.035242 6.78853 0 0 0.24264 82.9069 0 0 0 0
"forward-multipass opaque" 0.035442 6.67272 0 0 0 0 8.18007 29.9675 0 0
"lidr bitshift b1 16-bit backface opaque" 0.365001 6.64168 0 0 0 0 0 0 52.6437 15.2328
"lidr bitshift b2 16-bit backface opaque" 0.355668 6.72296 0 0 0 0 0 0 53.1483 18.2244
"lidr bitshift b4 16-bit backface opaque" 0.381666 6.77351 0 0 0 0 0 0 56.4846 25.5546
"lidr bitshift b8 16-bit backface opaque" 0.358091 6.79131 0 0 0 0 0 0 64.115 27.0575
"lidr bitshift b16 16-bit backface opaque" 0.348637 6.73018 0 0 0 0 0 0 121.362 36.0476
"lidr max-stencil b1 16-bit backface opaque" 0.363849 6.66852 0 0 0 0 0 0 52.0247 15.0686
"lidr max-stencil b2 16-bit backface opaque" 0.367465 12.3547 0 0 0 0 0 0 128.001 21.8385
"lidr max-stencil b4 16-bit backface opaque" 0.355848 6.63679 0 0 0 0 0 0 211.485 23.1523
"lidr max-stencil b8 16-bit backface opaque" 0.364661 6.8287 0 0 0 0 0 0 429.152 26.8482
"lidr max-stencil b16 16-bit backface opaque" 0.362223 6.7714 0 0 0 0 0 0 854.102 34.6427
"lidr cpu-sorted b1 16-bit backface opaque" 0.340094 6.80059 0 0 0 0 0 0 22.9843 19.6195
"lidr cpu-sorted b2 16-bit backface opaque" 0.36399 6.9857 0 0 0 0 0 0 23.4785 24.4763
"lidr cpu-sorted b4 16-bit backface opaque" 0.388086 6.98718 0 0 0 0 0 0 24.8796 31.166
"lidr cpu-sorted b8 16-bit backface opaque" 0.378591 6.83856 0 0 0 0 0 0 27.4411 46.2569
"lidr cpu-sorted b16 16-bit backface opaque" 0.377389 6.79108 0 0 0 0 0 0 30.9733 79.3055
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "brute-force", $P using 5 title "tile-depth-reduce", $P using 6 title "light-grid", $P using 7 title "tiled-forward", $P using 8 title "ambient", $P using 9 title "light-passes", $P using 10 title "light-volumes", $P using 11 title "forward"
