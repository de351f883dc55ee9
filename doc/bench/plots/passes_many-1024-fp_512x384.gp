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
"forward-brute opaque" 0.042063 4.64086 1369.99 0 0 0 0 0 0 0
"tiled min/max opaque" 0.032709 5.15402 0 0.649383 0.219195 31.6437 0 0 0 0
"tiled no-min/max opaque" 0.035593 4.61249 0 0 0.237542 43.252 0 0 0 0
"forward-multipass opaque" 0.032308 4.63525 0 0 0 0 8.37545 27.3074 0 0
"lidr bitshift b1 16-bit backface opaque" 0.306104 4.42076 0 0 0 0 0 0 35.732 9.33674
"lidr bitshift b2 16-bit backface opaque" 0.313905 4.43016 0 0 0 0 0 0 39.3591 10.5652
"lidr bitshift b4 16-bit backface opaque" 0.292604 4.47684 0 0 0 0 0 0 44.2468 19.3633
"lidr bitshift b8 16-bit backface opaque" 0.305463 4.55331 0 0 0 0 0 0 39.3982 14.8693
"lidr bitshift b16 16-bit backface opaque" 0.316349 4.70647 0 0 0 0 0 0 71.565 19.5019
"lidr max-stencil b1 16-bit backface opaque" 0.304171 4.60906 0 0 0 0 0 0 35.9621 9.18782
"lidr max-stencil b2 16-bit backface opaque" 0.322779 4.5508 0 0 0 0 0 0 63.2156 10.4918
"lidr max-stencil b4 16-bit backface opaque" 0.341897 4.6315 0 0 0 0 0 0 115.739 13.4119
"lidr max-stencil b8 16-bit backface opaque" 0.316039 4.51921 0 0 0 0 0 0 214.209 14.9498
"lidr max-stencil b16 16-bit backface opaque" 0.322188 4.74805 0 0 0 0 0 0 460.794 18.8884
"lidr cpu-sorted b1 16-bit backface opaque" 0.27029 4.52407 0 0 0 0 0 0 15.6075 11.2246
"lidr cpu-sorted b2 16-bit backface opaque" 0.300306 4.56226 0 0 0 0 0 0 16.3322 12.9905
"lidr cpu-sorted b4 16-bit backface opaque" 0.294958 5.80231 0 0 0 0 0 0 27.1577 19.3188
"lidr cpu-sorted b8 16-bit backface opaque" 0.34401 6.013 0 0 0 0 0 0 24.0365 26.5193
"lidr cpu-sorted b16 16-bit backface opaque" 0.344821 4.62927 0 0 0 0 0 0 23.4721 42.106
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "brute-force", $P using 5 title "tile-depth-reduce", $P using 6 title "light-grid", $P using 7 title "tiled-forward", $P using 8 title "ambient", $P using 9 title "light-passes", $P using 10 title "light-volumes", $P using 11 title "forward"
