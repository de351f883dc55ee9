set terminal pngcairo size 920,520 font 'sans,8' noenhanced
set output "passes_many-1024-top_512x384.png"
set title "per-pass breakdown: many-1024-top 512x384\noff scale: forward-brute opaque 3167 ms"
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
"tiled min/max opaque" 0.035223 6.39294 0.944541 0.230863 42.9928 0 0 0 0
"tiled no-min/max opaque" 0.03398 5.68959 0 0.241208 54.2264 0 0 0 0
"forward-multipass opaque" 0.032909 5.71591 0 0 0 7.36027 26.5412 0 0
"lidr bitshift b1 16-bit backface opaque" 0.354556 5.55162 0 0 0 0 0 27.8326 14.6779
"lidr bitshift b2 16-bit backface opaque" 0.380835 5.53825 0 0 0 0 0 28.7803 18.3794
"lidr bitshift b4 16-bit backface opaque" 0.402908 5.60008 0 0 0 0 0 30.538 27.1402
"lidr bitshift b8 16-bit backface opaque" 0.379492 5.52034 0 0 0 0 0 32.8773 25.1964
"lidr bitshift b16 16-bit backface opaque" 0.370229 5.60803 0 0 0 0 0 62.9964 33.7822
"lidr max-stencil b1 16-bit backface opaque" 0.360094 5.58905 0 0 0 0 0 27.7275 14.7785
"lidr max-stencil b2 16-bit backface opaque" 0.408075 5.61854 0 0 0 0 0 57.6234 18.1688
"lidr max-stencil b4 16-bit backface opaque" 0.366423 5.51181 0 0 0 0 0 111.665 24.5303
"lidr max-stencil b8 16-bit backface opaque" 0.380494 5.58887 0 0 0 0 0 222.59 25.1103
"lidr max-stencil b16 16-bit backface opaque" 0.359162 5.59185 0 0 0 0 0 446.261 32.7557
"lidr cpu-sorted b1 16-bit backface opaque" 0.373344 5.58474 0 0 0 0 0 11.9056 19.7997
"lidr cpu-sorted b2 16-bit backface opaque" 0.392512 5.63838 0 0 0 0 0 12.2281 24.075
"lidr cpu-sorted b4 16-bit backface opaque" 0.386624 5.72253 0 0 0 0 0 13.7024 33.7998
"lidr cpu-sorted b8 16-bit backface opaque" 0.369288 5.71293 0 0 0 0 0 16.1618 51.7004
"lidr cpu-sorted b16 16-bit backface opaque" 0.38464 5.74972 0 0 0 0 0 18.7904 89.5392
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
