set terminal pngcairo size 1400,520 font 'sans,8' noenhanced
set output "passes_many-1024-top_512x384.png"
set title "per-pass breakdown: many-1024-top 512x384\noff scale: forward-brute opaque 1480 ms"
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
"forward-multipass opaque" 0.029287 5.19636 6.53105 19.4381 0 0 0 0 0
"tiled min/max opaque" 0.032793 5.32856 0 0 0.799328 0.22057 23.6445 0 0
"tiled no-min/max opaque" 0.033964 5.15273 0 0 0 0.251027 29.5734 0 0
"auto opaque" 0.167077 5.00168 0 0 0 0 0 4.80375 10.8825
"lidr bitshift b1 16-bit sphere opaque" 0.700611 4.85423 0 0 0 0 0 4.52229 10.5869
"lidr bitshift b1 16-bit backface opaque" 0.5949 5.0664 0 0 0 0 0 11.9568 10.8252
"lidr bitshift b2 16-bit sphere opaque" 0.571746 5.36195 0 0 0 0 0 4.60292 11.1921
"lidr bitshift b2 16-bit backface opaque" 0.550305 4.93012 0 0 0 0 0 11.8827 11.3192
"lidr bitshift b4 16-bit sphere opaque" 0.470454 5.12948 0 0 0 0 0 5.24286 11.3398
"lidr bitshift b4 16-bit backface opaque" 0.492827 4.84147 0 0 0 0 0 12.771 11.9316
"lidr bitshift b8 16-bit sphere opaque" 0.563911 5.06882 0 0 0 0 0 7.2822 12.3966
"lidr bitshift b8 16-bit backface opaque" 0.535628 4.74313 0 0 0 0 0 15.3607 12.4313
"lidr bitshift b16 16-bit sphere opaque" 0.548612 5.04883 0 0 0 0 0 13.846 13.5628
"lidr bitshift b16 16-bit backface opaque" 0.513605 4.87433 0 0 0 0 0 23.5713 14.6642
"lidr max-stencil b1 16-bit sphere opaque" 0.56344 4.46654 0 0 0 0 0 4.46357 11.2485
"lidr max-stencil b1 16-bit backface opaque" 0.522482 4.52766 0 0 0 0 0 11.4307 11.2714
"lidr max-stencil b2 16-bit sphere opaque" 0.591053 4.66736 0 0 0 0 0 8.4057 11.5655
"lidr max-stencil b2 16-bit backface opaque" 0.471045 4.55309 0 0 0 0 0 24.4747 11.7408
"lidr max-stencil b4 16-bit sphere opaque" 0.553501 5.1444 0 0 0 0 0 16.4088 11.9713
"lidr max-stencil b4 16-bit backface opaque" 0.549865 4.94526 0 0 0 0 0 41.5586 12.5006
"lidr max-stencil b8 16-bit sphere opaque" 0.486134 4.61487 0 0 0 0 0 31.4071 12.0867
"lidr max-stencil b8 16-bit backface opaque" 0.546939 4.84135 0 0 0 0 0 77.9141 12.8954
"lidr max-stencil b16 16-bit sphere opaque" 0.498267 4.57925 0 0 0 0 0 62.0666 13.4653
"lidr max-stencil b16 16-bit backface opaque" 0.479431 4.49518 0 0 0 0 0 158.748 13.6632
"lidr cpu-sorted b1 16-bit sphere opaque" 0.466456 4.82247 0 0 0 0 0 4.88686 11.3992
"lidr cpu-sorted b1 16-bit backface opaque" 0.499449 4.64515 0 0 0 0 0 6.04281 11.1132
"lidr cpu-sorted b2 16-bit sphere opaque" 0.455835 4.62863 0 0 0 0 0 5.11472 12.7161
"lidr cpu-sorted b2 16-bit backface opaque" 0.559873 4.60579 0 0 0 0 0 6.2079 11.9857
"lidr cpu-sorted b4 16-bit sphere opaque" 0.496753 4.6721 0 0 0 0 0 5.88748 15.1882
"lidr cpu-sorted b4 16-bit backface opaque" 0.482556 5.13294 0 0 0 0 0 6.93463 14.3819
"lidr cpu-sorted b8 16-bit sphere opaque" 0.513575 4.7477 0 0 0 0 0 5.84347 18.9
"lidr cpu-sorted b8 16-bit backface opaque" 0.491964 5.09958 0 0 0 0 0 8.05277 19.0088
"lidr cpu-sorted b16 16-bit sphere opaque" 0.454935 5.19843 0 0 0 0 0 6.396 26.5515
"lidr cpu-sorted b16 16-bit backface opaque" 0.527222 5.23789 0 0 0 0 0 8.96349 26.799
"lidr auto sphere opaque" 0.161336 5.02297 0 0 0 0 0 4.8403 10.6298
"lidr auto backface opaque" 0.152309 5.00296 0 0 0 0 0 13.0537 11.7161
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
