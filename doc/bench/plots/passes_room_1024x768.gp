set terminal pngcairo size 1400,520 font 'sans,8' noenhanced
set output "passes_room_1024x768.png"
set title "per-pass breakdown: room 1024x768\noff scale: forward-brute opaque 1375 ms"
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
"forward-multipass opaque" 0.037461 10.6578 15.2547 44.5555 0 0 0 0 0
"tiled min/max opaque" 0.04183 12.0659 0 0 2.39372 0.251227 49.9719 0 0
"tiled no-min/max opaque" 0.053692 9.41838 0 0 0 0.303757 82.6924 0 0
"auto opaque" 0.116331 9.78233 0 0 0 0 0 24.1948 32.2905
"lidr bitshift b1 8-bit sphere opaque" 0.128474 12.3112 0 0 0 0 0 22.8666 31.8687
"lidr bitshift b1 8-bit backface opaque" 0.088036 10.1605 0 0 0 0 0 27.5726 37.1998
"lidr bitshift b1 8-bit exact opaque" 0.111242 12.044 0 0 0 0 0 49.2895 31.3361
"lidr bitshift b1 8-bit frontface opaque" 0.118155 11.4763 0 0 0 0 0 24.2187 36.1351
"lidr bitshift b2 8-bit sphere opaque" 0.105821 12.5919 0 0 0 0 0 24.5565 32.1812
"lidr bitshift b2 8-bit backface opaque" 0.074542 10.5323 0 0 0 0 0 27.917 36.2682
"lidr bitshift b2 8-bit exact opaque" 0.098126 12.2531 0 0 0 0 0 50.5515 32.4219
"lidr bitshift b2 8-bit frontface opaque" 0.076075 10.3324 0 0 0 0 0 27.3404 39.1879
"lidr bitshift b4 8-bit sphere opaque" 0.14748 14.7909 0 0 0 0 0 25.0384 33.3724
"lidr bitshift b4 8-bit backface opaque" 0.117113 11.4729 0 0 0 0 0 29.2495 37.5426
"lidr bitshift b4 8-bit exact opaque" 0.13699 12.4663 0 0 0 0 0 51.2962 33.4327
"lidr bitshift b4 8-bit frontface opaque" 0.098797 12.6304 0 0 0 0 0 28.2918 43.4484
"lidr bitshift b8 8-bit sphere opaque" 0.217192 11.9805 0 0 0 0 0 26.3515 33.2245
"lidr bitshift b8 8-bit backface opaque" 0.153341 12.086 0 0 0 0 0 34.4907 43.7879
"lidr bitshift b8 8-bit exact opaque" 0.125809 12.3172 0 0 0 0 0 53.1732 35.4374
"lidr bitshift b8 8-bit frontface opaque" 0.15258 15.5273 0 0 0 0 0 33.9377 48.3196
"lidr bitshift b16 8-bit sphere opaque" 0.135197 16.1858 0 0 0 0 0 61.0187 40.1278
"lidr bitshift b16 8-bit backface opaque" 0.161336 11.0927 0 0 0 0 0 55.3247 44.4802
"lidr bitshift b16 8-bit exact opaque" 0.088468 10.2554 0 0 0 0 0 124.53 38.9682
"lidr bitshift b16 8-bit frontface opaque" 0.150566 12.5119 0 0 0 0 0 58.409 56.8445
"lidr max-stencil b1 8-bit sphere opaque" 0.138823 10.5515 0 0 0 0 0 21.9804 31.3471
"lidr max-stencil b1 8-bit backface opaque" 0.167959 12.5422 0 0 0 0 0 27.8702 37.9042
"lidr max-stencil b1 8-bit exact opaque" 0.118646 15.2803 0 0 0 0 0 53.1368 34.6878
"lidr max-stencil b1 8-bit frontface opaque" 0.136339 12.3039 0 0 0 0 0 24.5424 36.8902
"lidr max-stencil b2 8-bit sphere opaque" 0.117042 12.3616 0 0 0 0 0 22.3499 34.5873
"lidr max-stencil b2 8-bit backface opaque" 0.164332 12.5406 0 0 0 0 0 28.9069 36.6917
"lidr max-stencil b2 8-bit exact opaque" 0.190723 12.0413 0 0 0 0 0 49.8551 34.8005
"lidr max-stencil b2 8-bit frontface opaque" 0.119186 9.94319 0 0 0 0 0 24.1904 43.4113
"lidr max-stencil b4 8-bit sphere opaque" 0.114187 16.4533 0 0 0 0 0 46.4569 36.8532
"lidr max-stencil b4 8-bit backface opaque" 0.157479 13.4387 0 0 0 0 0 55.2992 43.8219
"lidr max-stencil b4 8-bit exact opaque" 0.141359 16.1197 0 0 0 0 0 90.4565 35.3757
"lidr max-stencil b4 8-bit frontface opaque" 0.151077 12.2222 0 0 0 0 0 50.7972 45.8798
"lidr max-stencil b8 8-bit sphere opaque" 0.086624 11.4415 0 0 0 0 0 83.5374 36.3085
"lidr max-stencil b8 8-bit backface opaque" 0.144394 10.9504 0 0 0 0 0 91.9466 40.9916
"lidr max-stencil b8 8-bit exact opaque" 0.08982 10.114 0 0 0 0 0 162.564 34.4585
"lidr max-stencil b8 8-bit frontface opaque" 0.090271 10.8292 0 0 0 0 0 90.111 54.9666
"lidr max-stencil b16 8-bit sphere opaque" 0.118004 11.0665 0 0 0 0 0 166.123 36.9254
"lidr max-stencil b16 8-bit backface opaque" 0.109969 15.409 0 0 0 0 0 171.414 43.8836
"lidr max-stencil b16 8-bit exact opaque" 0.102856 10.1119 0 0 0 0 0 317.944 35.6061
"lidr max-stencil b16 8-bit frontface opaque" 0.135518 9.70551 0 0 0 0 0 167.821 53.4761
"lidr cpu-sorted b1 8-bit sphere opaque" 0.104128 9.86587 0 0 0 0 0 19.6367 33.0701
"lidr cpu-sorted b1 8-bit backface opaque" 0.092054 10.3805 0 0 0 0 0 14.2234 31.3664
"lidr cpu-sorted b1 8-bit exact opaque" 0.080853 9.78608 0 0 0 0 0 41.6395 32.1988
"lidr cpu-sorted b1 8-bit frontface opaque" 0.088237 10.3165 0 0 0 0 0 11.7713 32.9181
"lidr cpu-sorted b2 8-bit sphere opaque" 0.071747 9.85492 0 0 0 0 0 19.7249 33.4721
"lidr cpu-sorted b2 8-bit backface opaque" 0.069621 9.56085 0 0 0 0 0 13.4505 34.88
"lidr cpu-sorted b2 8-bit exact opaque" 0.072347 9.68751 0 0 0 0 0 41.7181 36.9312
"lidr cpu-sorted b2 8-bit frontface opaque" 0.077738 9.51102 0 0 0 0 0 12.2164 37.0262
"lidr cpu-sorted b4 8-bit sphere opaque" 0.078248 10.0394 0 0 0 0 0 21.2701 48.0057
"lidr cpu-sorted b4 8-bit backface opaque" 0.090091 9.67722 0 0 0 0 0 13.4296 41.4798
"lidr cpu-sorted b4 8-bit exact opaque" 0.084441 9.84625 0 0 0 0 0 49.3086 42.3187
"lidr cpu-sorted b4 8-bit frontface opaque" 0.073409 9.83696 0 0 0 0 0 14.2276 42.3799
"lidr cpu-sorted b8 8-bit sphere opaque" 0.081324 10.4128 0 0 0 0 0 26.8625 54.7427
"lidr cpu-sorted b8 8-bit backface opaque" 0.132392 10.9051 0 0 0 0 0 17.6575 58.3107
"lidr cpu-sorted b8 8-bit exact opaque" 0.123715 9.9084 0 0 0 0 0 44.6565 56.7636
"lidr cpu-sorted b8 8-bit frontface opaque" 0.085282 9.98124 0 0 0 0 0 15.6253 57.7597
"lidr cpu-sorted b16 8-bit sphere opaque" 0.076425 10.831 0 0 0 0 0 23.6622 90.6032
"lidr cpu-sorted b16 8-bit backface opaque" 0.113084 10.3457 0 0 0 0 0 17.0969 92.4404
"lidr cpu-sorted b16 8-bit exact opaque" 0.081105 10.196 0 0 0 0 0 44.7566 85.8428
"lidr cpu-sorted b16 8-bit frontface opaque" 0.074491 10.7684 0 0 0 0 0 19.2662 92.8096
"lidr auto sphere opaque" 0.160405 10.455 0 0 0 0 0 26.2301 33.2181
"lidr auto backface opaque" 0.139354 10.3845 0 0 0 0 0 55.1585 42.9161
"lidr auto exact opaque" 0.201232 11.9141 0 0 0 0 0 53.624 33.3672
"lidr auto frontface opaque" 0.125699 9.93006 0 0 0 0 0 55.7688 58.6469
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "ambient", $P using 5 title "light-passes", $P using 6 title "tile-depth-reduce", $P using 7 title "light-grid", $P using 8 title "tiled-forward", $P using 9 title "light-volumes", $P using 10 title "forward"
