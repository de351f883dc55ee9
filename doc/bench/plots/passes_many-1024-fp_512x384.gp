set terminal pngcairo size 1400,520 font 'sans,8' noenhanced
set output "passes_many-1024-fp_512x384.png"
set title "per-pass breakdown: many-1024-fp 512x384\noff scale: forward-brute opaque 1282 ms"
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
"forward-multipass opaque" 0.040577 5.96455 7.23057 24.6986 0 0 0 0 0
"tiled min/max opaque" 0.034576 6.91203 0 0 0.746728 0.280864 33.537 0 0
"tiled no-min/max opaque" 0.049033 5.51362 0 0 0 0.262318 44.7767 0 0
"auto opaque" 0.259463 5.70395 0 0 0 0 0 5.58267 11.5802
"lidr bitshift b1 16-bit sphere opaque" 0.80015 5.94389 0 0 0 0 0 4.65347 11.25
"lidr bitshift b1 16-bit backface opaque" 0.679671 6.08964 0 0 0 0 0 20.9522 12.113
"lidr bitshift b2 16-bit sphere opaque" 0.592947 6.23754 0 0 0 0 0 4.76163 11.266
"lidr bitshift b2 16-bit backface opaque" 0.606252 6.16498 0 0 0 0 0 19.507 12.0929
"lidr bitshift b4 16-bit sphere opaque" 0.717784 6.13337 0 0 0 0 0 5.56272 11.5918
"lidr bitshift b4 16-bit backface opaque" 0.682075 5.90563 0 0 0 0 0 20.7819 13.0744
"lidr bitshift b8 16-bit sphere opaque" 0.657199 6.18905 0 0 0 0 0 6.7361 12.151
"lidr bitshift b8 16-bit backface opaque" 0.653561 6.04692 0 0 0 0 0 25.122 14.0914
"lidr bitshift b16 16-bit sphere opaque" 0.643963 5.98952 0 0 0 0 0 14.0017 13.3696
"lidr bitshift b16 16-bit backface opaque" 0.652369 5.88576 0 0 0 0 0 41.4806 15.4578
"lidr max-stencil b1 16-bit sphere opaque" 0.715849 6.22898 0 0 0 0 0 4.69046 12.0399
"lidr max-stencil b1 16-bit backface opaque" 0.543692 6.40957 0 0 0 0 0 19.7745 12.2936
"lidr max-stencil b2 16-bit sphere opaque" 0.601342 6.12695 0 0 0 0 0 8.50288 11.4851
"lidr max-stencil b2 16-bit backface opaque" 0.649724 5.78105 0 0 0 0 0 35.1615 12.7855
"lidr max-stencil b4 16-bit sphere opaque" 0.622161 5.84097 0 0 0 0 0 16.6884 11.8318
"lidr max-stencil b4 16-bit backface opaque" 0.618395 5.9049 0 0 0 0 0 65.9085 13.5373
"lidr max-stencil b8 16-bit sphere opaque" 0.601753 5.89203 0 0 0 0 0 34.4682 12.0938
"lidr max-stencil b8 16-bit backface opaque" 0.683298 5.93022 0 0 0 0 0 130.534 15.7497
"lidr max-stencil b16 16-bit sphere opaque" 0.614136 6.18545 0 0 0 0 0 62.2118 12.5578
"lidr max-stencil b16 16-bit backface opaque" 0.552459 6.50912 0 0 0 0 0 239.693 19.4661
"lidr cpu-sorted b1 16-bit sphere opaque" 0.603356 5.82711 0 0 0 0 0 6.23202 11.7494
"lidr cpu-sorted b1 16-bit backface opaque" 0.541589 5.74071 0 0 0 0 0 9.44128 12.5262
"lidr cpu-sorted b2 16-bit sphere opaque" 0.571776 5.8714 0 0 0 0 0 7.14856 12.6066
"lidr cpu-sorted b2 16-bit backface opaque" 0.578179 5.64294 0 0 0 0 0 9.75013 12.8757
"lidr cpu-sorted b4 16-bit sphere opaque" 0.557519 5.80039 0 0 0 0 0 8.14131 15.2936
"lidr cpu-sorted b4 16-bit backface opaque" 0.705571 5.9386 0 0 0 0 0 11.0851 14.5165
"lidr cpu-sorted b8 16-bit sphere opaque" 0.598076 5.87493 0 0 0 0 0 8.15513 18.0721
"lidr cpu-sorted b8 16-bit backface opaque" 0.629306 5.61923 0 0 0 0 0 11.897 18.8229
"lidr cpu-sorted b16 16-bit sphere opaque" 0.658451 6.16398 0 0 0 0 0 8.9778 24.0748
"lidr cpu-sorted b16 16-bit backface opaque" 0.644244 5.88692 0 0 0 0 0 14.1524 25.3915
"lidr auto sphere opaque" 0.279902 5.94282 0 0 0 0 0 5.604 11.2368
"lidr auto backface opaque" 0.241529 5.72894 0 0 0 0 0 42.1977 15.3843
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
