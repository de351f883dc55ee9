set terminal pngcairo size 920,520 font 'sans,8' noenhanced
set output "passes_many-4096-fp_512x384.png"
set title "per-pass breakdown: many-4096-fp 512x384\noff scale: forward-brute opaque 5487 ms"
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
"tiled min/max opaque" 0.050134 7.56727 0.904502 0.569505 64.7817 0 0 0 0
"tiled no-min/max opaque" 0.051857 4.5835 0 0.599209 92.0464 0 0 0 0
"forward-multipass opaque" 0.045427 4.42311 0 0 0 5.25124 28.3826 0 0
"lidr bitshift b1 16-bit backface opaque" 0.468535 6.70701 0 0 0 0 0 115.508 15.5691
"lidr bitshift b2 16-bit backface opaque" 0.42475 5.86836 0 0 0 0 0 110.482 12.5032
"lidr bitshift b4 16-bit backface opaque" 0.440523 4.52112 0 0 0 0 0 96.1566 14.3862
"lidr bitshift b8 16-bit backface opaque" 0.426833 4.58835 0 0 0 0 0 107.961 15.5422
"lidr bitshift b16 16-bit backface opaque" 0.432621 4.64813 0 0 0 0 0 201.275 22.2887
"lidr max-stencil b1 16-bit backface opaque" 0.412231 4.55525 0 0 0 0 0 97.2213 10.8614
"lidr max-stencil b2 16-bit backface opaque" 0.445091 5.01246 0 0 0 0 0 193.309 11.6547
"lidr max-stencil b4 16-bit backface opaque" 0.432942 4.63904 0 0 0 0 0 364.381 15.6216
"lidr max-stencil b8 16-bit backface opaque" 0.435306 4.80091 0 0 0 0 0 714.189 15.1193
"lidr max-stencil b16 16-bit backface opaque" 0.406893 4.65047 0 0 0 0 0 1419.02 25.417
"lidr cpu-sorted b1 16-bit backface opaque" 0.419121 4.6385 0 0 0 0 0 48.6048 11.5362
"lidr cpu-sorted b2 16-bit backface opaque" 0.439682 4.46304 0 0 0 0 0 50.369 12.8913
"lidr cpu-sorted b4 16-bit backface opaque" 0.408716 4.51854 0 0 0 0 0 60.3745 18.1392
"lidr cpu-sorted b8 16-bit backface opaque" 0.43848 4.51446 0 0 0 0 0 77.1458 25.7166
"lidr cpu-sorted b16 16-bit backface opaque" 0.416688 4.55688 0 0 0 0 0 107.589 42.3482
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
