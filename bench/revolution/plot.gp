# Revolution mapping at a glance, three panels from the results of bench/revolution/run.sh:
#   1. march: silhouette mismatch against the iteration budget, per profile, with and without the proxy
#      bands (over-relaxation 1.6), the 0.5 % target and revolbake's default budget of 35 marked;
#   2. bake: seconds (exact distance + encode/decode/safety margin) against resolution, per encoding;
#   3. EDT: our binary EDT and OpenCV's distanceTransform, milliseconds against image size.
# Usage: gnuplot -e "dir='build-bench/results'; profiles='vase ring plate'; bake_profile='vase'" bench/revolution/plot.gp
# march.csv: 1 profile, 2 proxy, 3 omega, 4 iterations, 5 silhouette_mismatch, ...
# bake.csv:  1 profile, 2 resolution, 3 width, 4 height, 5 encoding, 6 distance_s, 7 encode_margin_s, ...
# edt.csv:   1 size, 2 ours_ms, 3 opencv_ms, 4 ours_over_opencv, ...
if (!exists("dir")) dir = 'build-bench/results'
if (!exists("profiles")) profiles = 'vase ring plate'
if (!exists("bake_profile")) bake_profile = 'vase'
set datafile separator ','
set terminal pngcairo size 1800,560 enhanced font ',10'
set output dir.'/revolution.png'
set multiplot layout 1,3
set grid

# Panel 1. A mismatch of 0 has no place on a log axis: drawn at the floor.
floor = 1e-5
mismatch(p, proxy) = (strcol(1) eq p && column(2) == proxy && abs(column(3) - 1.6) < 1e-6) ? \
                     (column(5) > floor ? column(5) : floor) : NaN
set title 'march: silhouette mismatch (omega 1.6); solid: proxy bands, dashed: none'
set logscale xy
set xlabel 'iteration budget'
set ylabel 'rays whose hit/miss differs / rays hitting either'
set format y '10^{%L}'
set xrange [9:300]
set xtics (10, 15, 20, 25, 35, 50, 64, 96, 128, 192, 256)
set key top right
set arrow 1 from graph 0, first 0.005 to graph 1, first 0.005 nohead dt 3 lw 1.5 lc 'black'
set arrow 2 from first 35, graph 0 to first 35, graph 1 nohead dt 3 lw 1.5 lc 'black'
set label 1 '0.5 % target' at graph 0.02, first 0.0058 left
plot for [k = 1:words(profiles)] dir.'/march.csv' using 4:(mismatch(word(profiles, k), 1)) skip 1 \
       with linespoints lc k pt 7 ps 0.7 dt 1 title word(profiles, k).' proxy', \
     for [k = 1:words(profiles)] dir.'/march.csv' using 4:(mismatch(word(profiles, k), 0)) skip 1 \
       with linespoints lc k pt 6 ps 0.7 dt 2 title word(profiles, k).' no proxy'
unset arrow 1
unset arrow 2
unset label 1
unset xtics
set xtics

# Panel 2. The encodings' rows interleave, so each series reads its own rows through awk. The distance
# field does not depend on the encoding: drawn once (from the float rows), dashed.
rows(e) = sprintf("< awk -F, '$1 == \"%s\" && $5 == \"%s\"' '%s/bake.csv'", bake_profile, e, dir)
set title sprintf('bake (%s): distance + encode/decode/margin', bake_profile)
set xlabel 'resolution (texels on the larger side)'
set ylabel 'seconds'
set format x '%g'
set xrange [200:5200]
set xtics (256, 512, 1024, 2048, 4096)
set key top left
plot for [e in 'float unorm16 sqrt8'] rows(e) using 2:($6 + $7) with linespoints pt 7 ps 0.8 title e, \
     rows('float') using 2:6 with linespoints dt 2 lc 'gray40' pt 6 title 'distance alone'
unset xtics
set xtics

# Panel 3.
set title 'binary EDT, uint8 image in, float distances out'
set xlabel 'image size (texels per side)'
set ylabel 'milliseconds'
set xrange [400:5200]
set xtics (512, 1024, 2048, 4096)
plot dir.'/edt.csv' using 1:2 skip 1 with linespoints pt 7 title 'ours (Felzenszwalb-Huttenlocher)', \
     dir.'/edt.csv' using 1:3 skip 1 with linespoints pt 5 title 'OpenCV distanceTransform'
unset multiplot
