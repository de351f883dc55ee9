set terminal pngcairo size 1400,520 font 'sans,8' noenhanced
set output "passes_room_1024x768.png"
set title "per-pass breakdown: room 1024x768\noff scale: forward-brute opaque 1292 ms"
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
"tiled min/max opaque" 0.02695 9.25448 1.75225 0.227818 47.5715 0 0 0 0
"tiled no-min/max opaque" 0.026689 7.69409 0 0.314136 71.1863 0 0 0 0
"forward-multipass opaque" 0.029053 7.71717 0 0 0 10.6778 36.9283 0 0
"lidr bitshift b1 8-bit backface opaque" 0.040219 9.49459 0 0 0 0 0 26.3183 24.6724
"lidr bitshift b1 8-bit exact opaque" 0.041401 9.51654 0 0 0 0 0 47.0076 24.7106
"lidr bitshift b1 8-bit frontface opaque" 0.042093 9.6502 0 0 0 0 0 24.7747 24.6929
"lidr bitshift b2 8-bit backface opaque" 0.04059 8.59559 0 0 0 0 0 26.0212 29.6896
"lidr bitshift b2 8-bit exact opaque" 0.0405 7.68472 0 0 0 0 0 41.4212 26.8811
"lidr bitshift b2 8-bit frontface opaque" 0.039749 7.56899 0 0 0 0 0 20.9683 26.1507
"lidr bitshift b4 8-bit backface opaque" 0.041241 7.72619 0 0 0 0 0 22.9078 36.4059
"lidr bitshift b4 8-bit exact opaque" 0.04093 7.54047 0 0 0 0 0 40.642 36.8548
"lidr bitshift b4 8-bit frontface opaque" 0.037285 7.56431 0 0 0 0 0 21.9758 36.3661
"lidr bitshift b8 8-bit backface opaque" 0.039769 7.50639 0 0 0 0 0 26.4261 36.4359
"lidr bitshift b8 8-bit exact opaque" 0.043164 7.5882 0 0 0 0 0 44.633 31.6956
"lidr bitshift b8 8-bit frontface opaque" 0.04034 7.68391 0 0 0 0 0 27.7986 45.7612
"lidr bitshift b16 8-bit backface opaque" 0.038938 7.52893 0 0 0 0 0 49.4417 42.2992
"lidr bitshift b16 8-bit exact opaque" 0.043074 7.57713 0 0 0 0 0 83.8349 37.3959
"lidr bitshift b16 8-bit frontface opaque" 0.040991 7.53627 0 0 0 0 0 47.1938 52.8989
"lidr max-stencil b1 8-bit backface opaque" 0.04025 7.51969 0 0 0 0 0 21.9486 22.1043
"lidr max-stencil b1 8-bit exact opaque" 0.040039 7.62427 0 0 0 0 0 40.1743 22.7029
"lidr max-stencil b1 8-bit frontface opaque" 0.039378 7.58147 0 0 0 0 0 20.3052 22.1798
"lidr max-stencil b2 8-bit backface opaque" 0.040981 7.63887 0 0 0 0 0 22.4539 26.149
"lidr max-stencil b2 8-bit exact opaque" 0.040761 7.59689 0 0 0 0 0 40.7733 26.6711
"lidr max-stencil b2 8-bit frontface opaque" 0.042914 7.561 0 0 0 0 0 20.7739 26.0957
"lidr max-stencil b4 8-bit backface opaque" 0.041962 7.5326 0 0 0 0 0 46.9021 35.0845
"lidr max-stencil b4 8-bit exact opaque" 0.043544 7.5155 0 0 0 0 0 73.9578 35.239
"lidr max-stencil b4 8-bit frontface opaque" 0.04039 7.80544 0 0 0 0 0 41.3724 35.0751
"lidr max-stencil b8 8-bit backface opaque" 0.043054 9.24534 0 0 0 0 0 93.2789 39.6695
"lidr max-stencil b8 8-bit exact opaque" 0.044596 9.32238 0 0 0 0 0 164.595 34.5844
"lidr max-stencil b8 8-bit frontface opaque" 0.042363 8.00741 0 0 0 0 0 76.2589 47.5108
"lidr max-stencil b16 8-bit backface opaque" 0.042494 7.53612 0 0 0 0 0 158.869 43.1881
"lidr max-stencil b16 8-bit exact opaque" 0.045577 9.31189 0 0 0 0 0 284.547 38.283
"lidr max-stencil b16 8-bit frontface opaque" 0.043704 9.34312 0 0 0 0 0 169.935 57.0681
"lidr cpu-sorted b1 8-bit backface opaque" 0.041982 9.38795 0 0 0 0 0 13.8827 32.263
"lidr cpu-sorted b1 8-bit exact opaque" 0.043905 9.50393 0 0 0 0 0 47.4455 32.4035
"lidr cpu-sorted b1 8-bit frontface opaque" 0.044947 9.39778 0 0 0 0 0 12.9167 32.6511
"lidr cpu-sorted b2 8-bit backface opaque" 0.046639 7.64341 0 0 0 0 0 10.3919 35.5767
"lidr cpu-sorted b2 8-bit exact opaque" 0.045638 7.66083 0 0 0 0 0 40.3363 36.0983
"lidr cpu-sorted b2 8-bit frontface opaque" 0.045767 7.67949 0 0 0 0 0 9.93892 35.7332
"lidr cpu-sorted b4 8-bit backface opaque" 0.044887 7.83231 0 0 0 0 0 10.9033 47.4121
"lidr cpu-sorted b4 8-bit exact opaque" 0.04717 7.68467 0 0 0 0 0 41.493 47.8028
"lidr cpu-sorted b4 8-bit frontface opaque" 0.046158 7.7641 0 0 0 0 0 10.3414 47.2547
"lidr cpu-sorted b8 8-bit backface opaque" 0.048081 7.76407 0 0 0 0 0 12.7374 73.7654
"lidr cpu-sorted b8 8-bit exact opaque" 0.047811 7.71356 0 0 0 0 0 41.9412 74.2328
"lidr cpu-sorted b8 8-bit frontface opaque" 0.046799 7.63744 0 0 0 0 0 11.9999 73.5744
"lidr cpu-sorted b16 8-bit backface opaque" 0.049013 7.6986 0 0 0 0 0 14.6674 133.7
"lidr cpu-sorted b16 8-bit exact opaque" 0.047931 7.60741 0 0 0 0 0 43.3682 133.538
"lidr cpu-sorted b16 8-bit frontface opaque" 0.048872 7.76794 0 0 0 0 0 14.5327 134.231
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
