# Paintstroke rasterization, error against time, from bench/stroke/run.sh's stroke.csv:
# largest per-pixel coverage error (left) and relative ink error (right) against CPU microseconds per
# stroke, ours (one point per piece length, 0.5 ... 4 px) and supersampling (2x2, 4x4, 8x8), per radius.
# Usage: gnuplot -e "dir='build-bench/results'" bench/stroke/plot.gp
# stroke.csv: 1 method, 2 radius, 3 knob, 4 cpu_us, 5 max_pixel_error, 6 ink_error, 7 pixels
if (!exists("dir")) dir = 'build-bench/results'
set datafile separator ','
set terminal pngcairo size 1400,560 enhanced font ',10'
set output dir.'/stroke.png'
set multiplot layout 1,2
set grid
set logscale xy
set xlabel 'CPU microseconds per stroke'
set format y '10^{%L}'
set key top right
radii = '0.5 1 1.5 3'
floor = 1e-7
pick(m, r, c) = (strcol(1) eq m && abs(column(2) - r) < 1e-9) ? (column(c) > floor ? column(c) : floor) : NaN
set title 'largest per-pixel coverage error (oracle: 32x32 samples per pixel)'
set ylabel 'max |alpha - area|'
plot for [i = 1:words(radii)] dir.'/stroke.csv' using 4:(pick('ours', word(radii, i) + 0, 5)) every ::1 \
       with linespoints lt i pt 7 title 'ours r '.word(radii, i), \
     for [i = 1:words(radii)] dir.'/stroke.csv' using 4:(pick('supersample', word(radii, i) + 0, 5)) every ::1 \
       with linespoints lt i pt 4 dt 2 title 'supersampling r '.word(radii, i)
set title 'total ink error (relative)'
set ylabel '|ink / oracle ink - 1|'
plot for [i = 1:words(radii)] dir.'/stroke.csv' using 4:(pick('ours', word(radii, i) + 0, 6)) every ::1 \
       with linespoints lt i pt 7 title 'ours r '.word(radii, i), \
     for [i = 1:words(radii)] dir.'/stroke.csv' using 4:(pick('supersample', word(radii, i) + 0, 6)) every ::1 \
       with linespoints lt i pt 4 dt 2 title 'supersampling r '.word(radii, i)
unset multiplot
