set terminal pngcairo size 1400,520 font 'sans,8' noenhanced
set output "passes_many-4096-fp_512x384.png"
set title "per-pass breakdown: many-4096-fp 512x384\noff scale: forward-brute opaque 4828 ms"
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
"forward-multipass opaque" 0.074021 6.08717 6.9477 29.7717 0 0 0 0 0
"tiled min/max opaque" 0.067077 6.59212 0 0 0.761867 0.678989 64.0898 0 0
"tiled no-min/max opaque" 0.085873 5.315 0 0 0 0.682155 89.5796 0 0
"auto opaque" 0.972278 5.16591 0 0 0 0 0 5.15275 10.6462
"lidr bitshift b1 16-bit sphere opaque" 1.58979 5.75807 0 0 0 0 0 4.32026 10.8479
"lidr bitshift b1 16-bit backface opaque" 1.54534 5.88513 0 0 0 0 0 33.3029 11.6537
"lidr bitshift b2 16-bit sphere opaque" 1.42792 5.88902 0 0 0 0 0 4.47663 10.6449
"lidr bitshift b2 16-bit backface opaque" 1.40303 5.67181 0 0 0 0 0 29.1764 12.2047
"lidr bitshift b4 16-bit sphere opaque" 1.38521 5.69864 0 0 0 0 0 5.33302 13.7664
"lidr bitshift b4 16-bit backface opaque" 1.35607 5.50676 0 0 0 0 0 28.2373 13.2393
"lidr bitshift b8 16-bit sphere opaque" 1.49282 6.23526 0 0 0 0 0 6.42008 11.4848
"lidr bitshift b8 16-bit backface opaque" 1.51953 5.58357 0 0 0 0 0 31.7411 13.0537
"lidr bitshift b16 16-bit sphere opaque" 1.44929 5.67633 0 0 0 0 0 11.1854 12.3456
"lidr bitshift b16 16-bit backface opaque" 1.47559 5.67475 0 0 0 0 0 55.0568 14.9144
"lidr max-stencil b1 16-bit sphere opaque" 1.42523 6.94489 0 0 0 0 0 4.5051 12.1979
"lidr max-stencil b1 16-bit backface opaque" 1.31165 5.44538 0 0 0 0 0 27.1188 11.4367
"lidr max-stencil b2 16-bit sphere opaque" 1.45724 5.44854 0 0 0 0 0 7.43 10.7984
"lidr max-stencil b2 16-bit backface opaque" 1.39301 5.91152 0 0 0 0 0 54.1751 11.5911
"lidr max-stencil b4 16-bit sphere opaque" 1.30369 5.86693 0 0 0 0 0 15.466 11.5119
"lidr max-stencil b4 16-bit backface opaque" 1.39121 6.01424 0 0 0 0 0 90.5803 14.6169
"lidr max-stencil b8 16-bit sphere opaque" 1.40833 7.96456 0 0 0 0 0 30.3802 12.1171
"lidr max-stencil b8 16-bit backface opaque" 1.54282 5.51437 0 0 0 0 0 167.681 12.7493
"lidr max-stencil b16 16-bit sphere opaque" 1.37058 5.79293 0 0 0 0 0 55.3766 12.5294
"lidr max-stencil b16 16-bit backface opaque" 1.40396 5.73359 0 0 0 0 0 332.331 13.4562
"lidr cpu-sorted b1 16-bit sphere opaque" 1.30452 5.81389 0 0 0 0 0 13.1213 11.0576
"lidr cpu-sorted b1 16-bit backface opaque" 1.33248 5.57998 0 0 0 0 0 13.5109 11.8935
"lidr cpu-sorted b2 16-bit sphere opaque" 1.28494 6.00361 0 0 0 0 0 15.7655 11.8161
"lidr cpu-sorted b2 16-bit backface opaque" 1.35863 5.7375 0 0 0 0 0 14.4903 12.5549
"lidr cpu-sorted b4 16-bit sphere opaque" 1.3563 5.76044 0 0 0 0 0 16.7715 13.7476
"lidr cpu-sorted b4 16-bit backface opaque" 1.38288 5.39606 0 0 0 0 0 15.1113 14.3242
"lidr cpu-sorted b8 16-bit sphere opaque" 1.34538 5.53162 0 0 0 0 0 16.5917 17.0909
"lidr cpu-sorted b8 16-bit backface opaque" 1.38272 5.50706 0 0 0 0 0 18.6761 17.5774
"lidr cpu-sorted b16 16-bit sphere opaque" 1.3908 5.93752 0 0 0 0 0 16.7304 23.6724
"lidr cpu-sorted b16 16-bit backface opaque" 1.3583 5.53022 0 0 0 0 0 19.4918 29.146
"lidr auto sphere opaque" 1.00348 5.73462 0 0 0 0 0 5.02537 11.1096
"lidr auto backface opaque" 1.00641 6.09588 0 0 0 0 0 59.1593 18.4805
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
