set terminal pngcairo size 1400,520 font 'sans,8' noenhanced
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
"forward-multipass" 0.019056 1.04527 1.8316 16.8211 0 0 0 0 0 0
"forward-brute" 0.018444 1.04656 0 0 136.971 0 0 0 0 0
"tiled min/max" 0.019947 1.32106 0 0 0 0.717483 0.073429 13.8085 0 0
"tiled no-min/max" 0.014418 1.04637 0 0 0 0 0.074621 13.9023 0 0
"auto" 0.018114 1.01461 0 0 0 0 0.083339 13.8928 0 0
"lidr bitshift b1 8-bit sphere" 0.053611 1.18094 0 0 0 0 0 0 4.20866 4.20093
"lidr bitshift b1 8-bit backface" 0.053822 1.02295 0 0 0 0 0 0 10.1985 4.21062
"lidr bitshift b2 8-bit sphere" 0.041498 1.10849 0 0 0 0 0 0 4.15456 4.24017
"lidr bitshift b2 8-bit backface" 0.03172 1.01969 0 0 0 0 0 0 10.8828 4.35491
"lidr bitshift b4 8-bit sphere" 0.046559 1.09028 0 0 0 0 0 0 4.10795 4.6909
"lidr bitshift b4 8-bit backface" 0.028123 1.00827 0 0 0 0 0 0 10.4998 4.79769
"lidr bitshift b8 8-bit sphere" 0.034766 1.0968 0 0 0 0 0 0 4.78355 5.61775
"lidr bitshift b8 8-bit backface" 0.034455 0.989519 0 0 0 0 0 0 11.3125 5.68852
"lidr bitshift b16 8-bit sphere" 0.033464 1.10293 0 0 0 0 0 0 9.21731 7.6138
"lidr bitshift b16 8-bit backface" 0.03126 1.03268 0 0 0 0 0 0 21.881 7.64202
"lidr max-stencil b1 8-bit sphere" 0.035608 1.09622 0 0 0 0 0 0 4.08883 4.43999
"lidr max-stencil b1 8-bit backface" 0.029385 0.985983 0 0 0 0 0 0 10.2348 4.45017
"lidr max-stencil b2 8-bit sphere" 0.029496 1.08776 0 0 0 0 0 0 4.00723 5.79511
"lidr max-stencil b2 8-bit backface" 0.045427 1.03781 0 0 0 0 0 0 10.1071 4.76354
"lidr max-stencil b4 8-bit sphere" 0.035217 1.12201 0 0 0 0 0 0 7.50116 5.05921
"lidr max-stencil b4 8-bit backface" 0.037111 0.965904 0 0 0 0 0 0 19.9241 5.2428
"lidr max-stencil b8 8-bit sphere" 0.04196 1.10054 0 0 0 0 0 0 15.0693 6.15603
"lidr max-stencil b8 8-bit backface" 0.034976 1.01913 0 0 0 0 0 0 38.3172 6.32503
"lidr max-stencil b16 8-bit sphere" 0.034946 1.07063 0 0 0 0 0 0 29.5726 8.08294
"lidr max-stencil b16 8-bit backface" 0.034376 1.00486 0 0 0 0 0 0 72.4531 8.09129
"lidr cpu-sorted b1 8-bit sphere" 0.049434 1.09487 0 0 0 0 0 0 3.70499 4.77166
"lidr cpu-sorted b1 8-bit backface" 0.027883 0.976876 0 0 0 0 0 0 5.12277 4.77521
"lidr cpu-sorted b2 8-bit sphere" 0.033523 1.09661 0 0 0 0 0 0 3.88778 5.46312
"lidr cpu-sorted b2 8-bit backface" 0.030928 0.978628 0 0 0 0 0 0 5.43698 5.38974
"lidr cpu-sorted b4 8-bit sphere" 0.030638 1.16761 0 0 0 0 0 0 4.05833 6.67795
"lidr cpu-sorted b4 8-bit backface" 0.032132 0.978839 0 0 0 0 0 0 5.7477 6.60314
"lidr cpu-sorted b8 8-bit sphere" 0.030819 1.04655 0 0 0 0 0 0 5.1662 9.5492
"lidr cpu-sorted b8 8-bit backface" 0.034807 1.01855 0 0 0 0 0 0 7.16796 9.67842
"lidr cpu-sorted b16 8-bit sphere" 0.036991 1.11808 0 0 0 0 0 0 5.72676 16.3259
"lidr cpu-sorted b16 8-bit backface" 0.040827 0.957508 0 0 0 0 0 0 8.64069 16.0565
"lidr auto sphere" 0.047741 1.04446 0 0 0 0 0 0 9.89596 7.71033
"lidr auto backface" 0.039946 0.988338 0 0 0 0 0 0 22.4789 7.72502
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "brute-force", $P using 7 title "tile-depth-reduce", $P using 8 title "light-grid", $P using 9 title "tiled-forward", $P using 10 title "light-volumes", $P using 11 title "forward"
