set terminal pngcairo size 1400,520 font 'sans,8' noenhanced
set output "passes_many-4096-top_512x384.png"
set title "per-pass breakdown: many-4096-top 512x384\noff scale: forward-brute opaque 6029 ms"
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
"forward-multipass opaque" 0.059604 5.41358 9.49884 24.9777 0 0 0 0 0
"tiled min/max opaque" 0.058912 5.46391 0 0 0.792506 0.60547 34.8251 0 0
"tiled no-min/max opaque" 0.05797 4.99659 0 0 0 0.611853 50.5285 0 0
"auto opaque" 0.641038 5.01996 0 0 0 0 0 5.48359 11.1894
"lidr bitshift b1 16-bit sphere opaque" 1.40853 5.04706 0 0 0 0 0 4.63551 10.7812
"lidr bitshift b1 16-bit backface opaque" 1.17011 5.3711 0 0 0 0 0 22.921 11.0221
"lidr bitshift b2 16-bit sphere opaque" 1.083 5.28212 0 0 0 0 0 4.61149 10.8647
"lidr bitshift b2 16-bit backface opaque" 1.06423 5.18527 0 0 0 0 0 23.4694 11.5182
"lidr bitshift b4 16-bit sphere opaque" 1.07182 5.17765 0 0 0 0 0 5.39826 11.0275
"lidr bitshift b4 16-bit backface opaque" 1.0429 5.30175 0 0 0 0 0 22.8239 11.8892
"lidr bitshift b8 16-bit sphere opaque" 1.17894 5.2768 0 0 0 0 0 6.93118 12.0192
"lidr bitshift b8 16-bit backface opaque" 1.09058 4.98558 0 0 0 0 0 23.0977 16.414
"lidr bitshift b16 16-bit sphere opaque" 1.18997 5.32924 0 0 0 0 0 14.2794 13.3586
"lidr bitshift b16 16-bit backface opaque" 1.03289 4.95529 0 0 0 0 0 41.7855 14.0392
"lidr max-stencil b1 16-bit sphere opaque" 1.15214 4.85413 0 0 0 0 0 4.66958 10.9457
"lidr max-stencil b1 16-bit backface opaque" 0.977337 4.90554 0 0 0 0 0 20.4771 10.9268
"lidr max-stencil b2 16-bit sphere opaque" 1.05476 5.04198 0 0 0 0 0 8.27084 11.2588
"lidr max-stencil b2 16-bit backface opaque" 0.999308 5.13752 0 0 0 0 0 35.4912 11.4897
"lidr max-stencil b4 16-bit sphere opaque" 1.0732 5.23112 0 0 0 0 0 15.7722 12.033
"lidr max-stencil b4 16-bit backface opaque" 0.95873 5.05848 0 0 0 0 0 71.2368 12.0232
"lidr max-stencil b8 16-bit sphere opaque" 0.996763 5.21694 0 0 0 0 0 31.4952 12.1183
"lidr max-stencil b8 16-bit backface opaque" 0.960013 4.91107 0 0 0 0 0 115.285 12.5837
"lidr max-stencil b16 16-bit sphere opaque" 0.993096 5.29381 0 0 0 0 0 60.6471 12.9094
"lidr max-stencil b16 16-bit backface opaque" 1.02894 5.16405 0 0 0 0 0 232.018 13.5319
"lidr cpu-sorted b1 16-bit sphere opaque" 0.989861 5.29436 0 0 0 0 0 8.15679 11.2631
"lidr cpu-sorted b1 16-bit backface opaque" 0.952058 4.97472 0 0 0 0 0 9.12793 11.1168
"lidr cpu-sorted b2 16-bit sphere opaque" 0.992595 5.19911 0 0 0 0 0 8.87248 12.3115
"lidr cpu-sorted b2 16-bit backface opaque" 1.10177 5.06602 0 0 0 0 0 9.09716 11.8264
"lidr cpu-sorted b4 16-bit sphere opaque" 0.981934 5.18674 0 0 0 0 0 9.37446 14.7257
"lidr cpu-sorted b4 16-bit backface opaque" 1.01041 5.00119 0 0 0 0 0 11.181 14.3916
"lidr cpu-sorted b8 16-bit sphere opaque" 0.966486 5.03077 0 0 0 0 0 9.61603 19.0805
"lidr cpu-sorted b8 16-bit backface opaque" 1.04268 4.94558 0 0 0 0 0 14.3055 18.7124
"lidr cpu-sorted b16 16-bit sphere opaque" 1.05378 5.24466 0 0 0 0 0 10.1573 26.6041
"lidr cpu-sorted b16 16-bit backface opaque" 1.12353 5.13289 0 0 0 0 0 15.7088 27.5826
"lidr auto sphere opaque" 0.628675 5.26812 0 0 0 0 0 8.15123 11.65
"lidr auto backface opaque" 0.622883 4.92824 0 0 0 0 0 22.5013 12.4823
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
