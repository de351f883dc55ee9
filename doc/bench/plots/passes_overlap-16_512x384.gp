set terminal pngcairo size 950,520 font 'sans,8' noenhanced
set output "passes_overlap-16_512x384.png"
set title "per-pass breakdown: overlap-16 512x384"
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
"forward-brute" 0.033529 1.09622 292.591 0 0 0 0 0 0 0
"tiled min/max" 0.029343 1.44344 0 0.820186 0.074912 29.3128 0 0 0 0
"tiled no-min/max" 0.034982 1.24111 0 0 0.089543 26.6956 0 0 0 0
"forward-multipass" 0.025538 1.11547 0 0 0 0 1.97332 23.6822 0 0
"lidr bitshift b1 8-bit backface" 0.03387 1.03793 0 0 0 0 0 0 13.4649 6.47548
"lidr bitshift b2 8-bit backface" 0.037556 0.994685 0 0 0 0 0 0 13.8933 8.09676
"lidr bitshift b4 8-bit backface" 0.041611 1.06541 0 0 0 0 0 0 14.4334 12.5125
"lidr bitshift b8 8-bit backface" 0.039839 1.07045 0 0 0 0 0 0 16.5534 11.3619
"lidr bitshift b16 8-bit backface" 0.045738 1.07964 0 0 0 0 0 0 32.7435 15.9561
"lidr max-stencil b1 8-bit backface" 0.038177 1.04451 0 0 0 0 0 0 13.4885 6.56143
"lidr max-stencil b2 8-bit backface" 0.045728 1.05345 0 0 0 0 0 0 14.098 8.32808
"lidr max-stencil b4 8-bit backface" 0.047049 1.08825 0 0 0 0 0 0 28.8842 12
"lidr max-stencil b8 8-bit backface" 0.046209 1.10792 0 0 0 0 0 0 58.1233 11.8498
"lidr max-stencil b16 8-bit backface" 0.04744 1.09804 0 0 0 0 0 0 116.558 16.5371
"lidr cpu-sorted b1 8-bit backface" 0.040691 1.03902 0 0 0 0 0 0 6.18656 9.60526
"lidr cpu-sorted b2 8-bit backface" 0.036644 1.07643 0 0 0 0 0 0 6.38334 11.8843
"lidr cpu-sorted b4 8-bit backface" 0.043936 1.10475 0 0 0 0 0 0 7.11024 16.6932
"lidr cpu-sorted b8 8-bit backface" 0.046259 1.08485 0 0 0 0 0 0 8.48694 27.632
"lidr cpu-sorted b16 8-bit backface" 0.054982 1.11477 0 0 0 0 0 0 10.9889 55.6325
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "brute-force", $P using 5 title "tile-depth-reduce", $P using 6 title "light-grid", $P using 7 title "tiled-forward", $P using 8 title "ambient", $P using 9 title "light-passes", $P using 10 title "light-volumes", $P using 11 title "forward"
