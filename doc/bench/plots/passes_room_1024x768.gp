set terminal pngcairo size 1400,520 font 'sans,8' noenhanced
set output "passes_room_1024x768.png"
set title "per-pass breakdown: room 1024x768\noff scale: forward-brute opaque 2673 ms"
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
"tiled min/max opaque" 0.02722 9.15643 1.59569 0.231964 46.9914 0 0 0 0
"tiled no-min/max opaque" 0.027892 9.7123 0 0.277892 74.6003 0 0 0 0
"forward-multipass opaque" 0.030405 10.3753 0 0 0 13.7229 39.9022 0 0
"lidr bitshift b1 8-bit backface opaque" 0.043345 19.9117 0 0 0 0 0 46.1797 48.0382
"lidr bitshift b1 8-bit exact opaque" 0.043955 15.9189 0 0 0 0 0 92.017 47.8676
"lidr bitshift b1 8-bit frontface opaque" 0.043885 12.4571 0 0 0 0 0 34.8103 42.0746
"lidr bitshift b2 8-bit backface opaque" 0.041933 13.5486 0 0 0 0 0 44.2168 49.1015
"lidr bitshift b2 8-bit exact opaque" 0.043635 13.2116 0 0 0 0 0 75.9581 51.2668
"lidr bitshift b2 8-bit frontface opaque" 0.041882 12.5887 0 0 0 0 0 36.5863 50.008
"lidr bitshift b4 8-bit backface opaque" 0.043665 13.1999 0 0 0 0 0 50.5776 76.0808
"lidr bitshift b4 8-bit exact opaque" 0.042894 12.7257 0 0 0 0 0 70.3863 72.5394
"lidr bitshift b4 8-bit frontface opaque" 0.045047 12.5344 0 0 0 0 0 37.8354 69.9111
"lidr bitshift b8 8-bit backface opaque" 0.045618 12.4863 0 0 0 0 0 46.0503 70.9436
"lidr bitshift b8 8-bit exact opaque" 0.041392 12.565 0 0 0 0 0 75.7814 61.667
"lidr bitshift b8 8-bit frontface opaque" 0.043925 15.929 0 0 0 0 0 56.7865 96.7496
"lidr bitshift b16 8-bit backface opaque" 0.044265 7.65107 0 0 0 0 0 47.3762 43.9237
"lidr bitshift b16 8-bit exact opaque" 0.044907 7.90052 0 0 0 0 0 94.6904 38.9539
"lidr bitshift b16 8-bit frontface opaque" 0.044055 7.63081 0 0 0 0 0 49.1715 53.5224
"lidr max-stencil b1 8-bit backface opaque" 0.041602 7.62622 0 0 0 0 0 22.7881 22.5541
"lidr max-stencil b1 8-bit exact opaque" 0.041641 7.61551 0 0 0 0 0 41.4267 23.1032
"lidr max-stencil b1 8-bit frontface opaque" 0.042202 7.48857 0 0 0 0 0 20.9256 22.8334
"lidr max-stencil b2 8-bit backface opaque" 0.042003 7.60087 0 0 0 0 0 22.3988 26.3235
"lidr max-stencil b2 8-bit exact opaque" 0.041782 7.53786 0 0 0 0 0 39.7358 26.656
"lidr max-stencil b2 8-bit frontface opaque" 0.043885 7.81985 0 0 0 0 0 21.8457 26.6374
"lidr max-stencil b4 8-bit backface opaque" 0.046549 7.55827 0 0 0 0 0 44.457 35.0347
"lidr max-stencil b4 8-bit exact opaque" 0.045408 7.66941 0 0 0 0 0 75.132 35.16
"lidr max-stencil b4 8-bit frontface opaque" 0.044296 7.61605 0 0 0 0 0 41.0492 35.4738
"lidr max-stencil b8 8-bit backface opaque" 0.043675 7.55429 0 0 0 0 0 82.6271 38.213
"lidr max-stencil b8 8-bit exact opaque" 0.047941 7.66904 0 0 0 0 0 145.623 32.5522
"lidr max-stencil b8 8-bit frontface opaque" 0.043354 7.49865 0 0 0 0 0 76.3129 47.4701
"lidr max-stencil b16 8-bit backface opaque" 0.048171 7.61784 0 0 0 0 0 159.069 43.9024
"lidr max-stencil b16 8-bit exact opaque" 0.04755 7.52495 0 0 0 0 0 282.935 37.1002
"lidr max-stencil b16 8-bit frontface opaque" 0.045467 7.62806 0 0 0 0 0 146.479 57.0685
"lidr cpu-sorted b1 8-bit backface opaque" 0.045637 7.56531 0 0 0 0 0 10.1957 29.5836
"lidr cpu-sorted b1 8-bit exact opaque" 0.049293 7.9524 0 0 0 0 0 43.351 30.8026
"lidr cpu-sorted b1 8-bit frontface opaque" 0.048041 7.93413 0 0 0 0 0 11.1429 32.052
"lidr cpu-sorted b2 8-bit backface opaque" 0.049543 7.61865 0 0 0 0 0 10.5406 35.7106
"lidr cpu-sorted b2 8-bit exact opaque" 0.048733 7.78198 0 0 0 0 0 42.5872 36.9786
"lidr cpu-sorted b2 8-bit frontface opaque" 0.045037 7.68041 0 0 0 0 0 9.8065 35.7061
"lidr cpu-sorted b4 8-bit backface opaque" 0.051326 7.86848 0 0 0 0 0 11.2244 48.4727
"lidr cpu-sorted b4 8-bit exact opaque" 0.048572 7.72605 0 0 0 0 0 42.0504 48.4408
"lidr cpu-sorted b4 8-bit frontface opaque" 0.045998 7.74869 0 0 0 0 0 10.3145 47.2428
"lidr cpu-sorted b8 8-bit backface opaque" 0.04675 7.59131 0 0 0 0 0 12.4088 73.5255
"lidr cpu-sorted b8 8-bit exact opaque" 0.053599 7.80951 0 0 0 0 0 44.9446 74.1847
"lidr cpu-sorted b8 8-bit frontface opaque" 0.051356 7.81564 0 0 0 0 0 12.0709 73.7595
"lidr cpu-sorted b16 8-bit backface opaque" 0.051256 7.57866 0 0 0 0 0 14.7195 133.746
"lidr cpu-sorted b16 8-bit exact opaque" 0.05416 7.77443 0 0 0 0 0 43.4035 135.526
"lidr cpu-sorted b16 8-bit frontface opaque" 0.052037 7.75855 0 0 0 0 0 14.8458 134.013
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
