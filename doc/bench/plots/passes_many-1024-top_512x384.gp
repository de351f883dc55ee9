set terminal pngcairo size 920,520 font 'sans,8' noenhanced
set output "passes_many-1024-top_512x384.png"
set title "per-pass breakdown: many-1024-top 512x384\noff scale: forward-brute opaque 1618 ms"
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
"tiled min/max opaque" 0.032017 4.25682 0.603194 0.197543 24.595 0 0 0 0
"tiled no-min/max opaque" 0.035523 4.01691 0 0.238323 29.3548 0 0 0 0
"forward-multipass opaque" 0.031447 4.14532 0 0 0 4.91385 18.4259 0 0
"lidr bitshift b1 16-bit backface opaque" 0.314016 3.73885 0 0 0 0 0 19.1691 8.68265
"lidr bitshift b2 16-bit backface opaque" 0.30274 3.71958 0 0 0 0 0 19.716 11.4425
"lidr bitshift b4 16-bit backface opaque" 0.308858 3.73786 0 0 0 0 0 20.7728 14.6993
"lidr bitshift b8 16-bit backface opaque" 0.315708 3.76622 0 0 0 0 0 21.1492 14.1785
"lidr bitshift b16 16-bit backface opaque" 0.314987 3.82355 0 0 0 0 0 37.7506 18.4497
"lidr max-stencil b1 16-bit backface opaque" 0.326063 3.78781 0 0 0 0 0 24.0777 8.6685
"lidr max-stencil b2 16-bit backface opaque" 0.337611 3.83734 0 0 0 0 0 37.0691 10.21
"lidr max-stencil b4 16-bit backface opaque" 0.337811 3.80339 0 0 0 0 0 66.134 13.5586
"lidr max-stencil b8 16-bit backface opaque" 0.301838 3.7655 0 0 0 0 0 121.557 13.8462
"lidr max-stencil b16 16-bit backface opaque" 0.277371 3.76514 0 0 0 0 0 238.35 18.1494
"lidr cpu-sorted b1 16-bit backface opaque" 0.277742 3.79639 0 0 0 0 0 8.28726 10.8852
"lidr cpu-sorted b2 16-bit backface opaque" 0.293405 3.83593 0 0 0 0 0 8.73777 13.2829
"lidr cpu-sorted b4 16-bit backface opaque" 0.294778 3.72176 0 0 0 0 0 9.09929 17.633
"lidr cpu-sorted b8 16-bit backface opaque" 0.340535 3.72447 0 0 0 0 0 11.4907 27.0206
"lidr cpu-sorted b16 16-bit backface opaque" 0.341717 3.76621 0 0 0 0 0 13.0113 46.9087
EOD
plot $P using 2:xtic(1) title "light-table", $P using 3 title "depth-prepass", $P using 4 title "tile-depth-reduce", $P using 5 title "light-grid", $P using 6 title "tiled-forward", $P using 7 title "ambient", $P using 8 title "light-passes", $P using 9 title "light-volumes", $P using 10 title "forward"
