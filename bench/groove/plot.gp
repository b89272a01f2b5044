# Groove shading at a glance, from the results of bench/groove/run.sh (groove.csv):
#   1. every view: the method's RMSE against the reference, over the method's time per frame, with the
#      reference's own noise floor (RMSE between two seeds) of the same view as open circles;
#   2. the V-groove view sweeps: RMSE / noise floor against the view angle (criterion: 3), the method as
#      shipped and as the seed publishes it (uniform footprint segment), on a groove along the pixels'
#      columns (where both densities agree) and on a diagonal one;
#   3. the dense parallel set: the same against footprint / groove width.
# Usage: gnuplot -e "dir='build-bench/results'" bench/groove/plot.gp
# groove.csv: 1 case, 2 scene, 3 width, 4 pixels, 5 view_theta, 6 view_phi, 7 light_theta, 8 light_phi,
#   9 bounces, 10 footprint_over_width, 11 special_fraction, 12 method_frame_s (wall), 13 method_ns_per_pixel (CPU),
#   14 reference_frame_s (wall), 15 reference_ns_per_pixel (CPU), 16 cost_ratio (CPU), 17 rmse, 18 relative_mse, 19 p99,
#   20 max, 21 noise_floor, 22 rmse_over_floor, 23 seed_rmse, 24 seed_rmse_over_floor
if (!exists("dir")) dir = 'build-bench/results'
set datafile separator ','
set terminal pngcairo size 1800,560 enhanced font ',10'
set output dir.'/groove.png'
set multiplot layout 1,3
set grid
cases = system(sprintf("awk -F, 'NR > 1 && !seen[$1]++ { printf \"%%s \", $1 }' '%s/groove.csv'", dir))
rows(c) = sprintf("< awk -F, 'NR > 1 && $1 == \"%s\"' '%s/groove.csv'", c, dir)

set title 'error against time per frame (filled: method; open: reference noise floor)'
set logscale xy
set xlabel 'method seconds per frame (fastest of the repeats)'
set ylabel 'RMSE against the reference'
set key outside bottom center horizontal maxrows 3 font ',8'
plot for [k = 1:words(cases)] rows(word(cases, k)) using 12:($17 > 0 ? $17 : 1e-9) with points pt 7 lc k title word(cases, k), \
     for [k = 1:words(cases)] rows(word(cases, k)) using 12:21 with points pt 6 lc k notitle
unset logscale

set title 'V-groove: error against view angle (an exact 0 is drawn at 1e-3)'
set key inside top left
set logscale y
set xlabel 'view angle from the normal (degrees)'
set ylabel 'RMSE / reference noise floor'
set arrow 1 from graph 0, first 3 to graph 1, first 3 nohead dt 3 lw 1.5 lc 'black'
plot rows('vgroove-view-sweep') using 5:($22 > 0 ? $22 : 1e-3) with linespoints pt 7 lc 1 title 'along the pixels: method', \
     rows('vgroove-view-sweep') using 5:($24 > 0 ? $24 : 1e-3) with linespoints pt 6 lc 1 dt 2 title "along the pixels: seed's segment", \
     rows('vgroove-diagonal-view-sweep') using 5:($22 > 0 ? $22 : 1e-3) with linespoints pt 7 lc 2 title 'diagonal: method', \
     rows('vgroove-diagonal-view-sweep') using 5:($24 > 0 ? $24 : 1e-3) with linespoints pt 6 lc 2 dt 2 title "diagonal: seed's segment"

set title 'dense parallel grooves: error against footprint / width (an exact 0 is drawn at 1e-3)'
set logscale xy
set xlabel 'footprint / groove width'
plot rows('dense-parallel') using 10:($22 > 0 ? $22 : 1e-3) with points pt 7 title 'method (trapezoid density)', \
     rows('dense-parallel') using 10:($24 > 0 ? $24 : 1e-3) with points pt 6 title "seed's segment", \
     rows('dense-parallel') using 10:($26 > 0 ? $26 : 1e-3) with points pt 2 ps 1.5 title 'runtime (bakeplay, far level past 24 primitives)'
unset arrow 1
unset multiplot
