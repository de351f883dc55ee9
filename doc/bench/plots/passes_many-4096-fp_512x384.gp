set terminal pngcairo size 920,520 font 'sans,8' noenhanced
set output "passes_many-4096-fp_512x384.png"
set title "per-pass breakdown: many-4096-fp 512x384\noff scale: forward-brute opaque 5626 ms"
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
"tiled min/max opaque" 0.050575 7.67661 0.906384 0.576835 125.047 0 0 0 0
"tiled no-min/max opaque" 0.054571 6.83066 0 0.632818 181.263 0 0 0 0
"forward-multipass opaque" 0.054271 6.85985 0 0 0 8.45469 36.412 0 0
"lidr bitshift b1 16-bit backface opaque" 0.484869 4.64508 0 0 0 0 0 104.236 9.26436
"lidr bitshift b2 16-bit backface opaque" 0.49905 4.77146 0 0 0 0 0 102.797 11.8466
"lidr bitshift b4 16-bit backface opaque" 0.459602 4.7165 0 0 0 0 0 101.939 16.0995
"lidr bitshift b8 16-bit backface opaque" 0.47173 4.65401 0 0 0 0 0 104.377 15.4627
"lidr bitshift b16 16-bit backface opaque" 0.519 4.76634 0 0 0 0 0 202.524 19.667
"lidr max-stencil b1 16-bit backface opaque" 0.496346 4.68432 0 0 0 0 0 100.566 10.2605
"lidr max-stencil b2 16-bit backface opaque" 0.501864 4.8342 0 0 0 0 0 206.631 11.1639
"lidr max-stencil b4 16-bit backface opaque" 0.481444 4.7663 0 0 0 0 0 382.352 14.8813
"lidr max-stencil b8 16-bit backface opaque" 0.469996 5.27979 0 0 0 0 0 811.278 18.6173
"lidr max-stencil b16 16-bit backface opaque" 0.483508 6.73228 0 0 0 0 0 1562.65 22.9483
"lidr cpu-sorted b1 16-bit backface opaque" 0.463317 4.70435 0 0 0 0 0 50.2856 11.6915
"lidr cpu-sorted b2 16-bit backface opaque" 0.478239 6.96056 0 0 0 0 0 72.5885 23.8161
"lidr cpu-sorted b4 16-bit backface opaque" 0.445231 6.93974 0 0 0 0 0 82.471 31.5052
"lidr cpu-sorted b8 16-bit backface opaque" 0.509075 6.87067 0 0 0 0 0 98.8771 47.3816
"lidr cpu-sorted b16 16-bit backface opaque" 0.468705 6.89312 0 0 0 0 0 128.668 79.936
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
