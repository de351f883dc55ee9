set terminal pngcairo size 920,520 font 'sans,8' noenhanced
set output "passes_many-4096-top_512x384.png"
set title "per-pass breakdown: many-4096-top 512x384\noff scale: forward-brute opaque 6435 ms"
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
"tiled min/max opaque" 0.057816 5.74383 0.729863 0.553281 35.945 0 0 0 0
"tiled no-min/max opaque" 0.056113 5.02353 0 0.571938 55.8742 0 0 0 0
"forward-multipass opaque" 0.051857 3.97335 0 0 0 4.91848 22.719 0 0
"lidr bitshift b1 16-bit backface opaque" 0.466122 4.01059 0 0 0 0 0 59.8009 9.72879
"lidr bitshift b2 16-bit backface opaque" 0.459842 3.84575 0 0 0 0 0 50.312 14.1531
"lidr bitshift b4 16-bit backface opaque" 0.442596 3.86019 0 0 0 0 0 56.689 15.1783
"lidr bitshift b8 16-bit backface opaque" 0.45814 4.06093 0 0 0 0 0 61.7565 15.6908
"lidr bitshift b16 16-bit backface opaque" 0.452642 5.16604 0 0 0 0 0 97.9678 22.0281
"lidr max-stencil b1 16-bit backface opaque" 0.471259 5.53936 0 0 0 0 0 61.63 9.99583
"lidr max-stencil b2 16-bit backface opaque" 0.448646 5.12549 0 0 0 0 0 104.919 11.547
"lidr max-stencil b4 16-bit backface opaque" 0.467604 5.30755 0 0 0 0 0 196.731 15.8508
"lidr max-stencil b8 16-bit backface opaque" 0.48569 5.27869 0 0 0 0 0 390.368 16.6098
"lidr max-stencil b16 16-bit backface opaque" 0.462736 4.05921 0 0 0 0 0 729.743 18.0219
"lidr cpu-sorted b1 16-bit backface opaque" 0.444329 3.83927 0 0 0 0 0 25.5755 11.2619
"lidr cpu-sorted b2 16-bit backface opaque" 0.425921 3.9586 0 0 0 0 0 26.1572 13.4869
"lidr cpu-sorted b4 16-bit backface opaque" 0.442126 3.87079 0 0 0 0 0 38.4198 18.9511
"lidr cpu-sorted b8 16-bit backface opaque" 0.464959 3.8676 0 0 0 0 0 50.7846 27.7694
"lidr cpu-sorted b16 16-bit backface opaque" 0.483868 3.86525 0 0 0 0 0 60.54 49.3674
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
