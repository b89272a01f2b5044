# Tonal art maps at a glance, from the results of bench/tam/run.sh: for each finest resolution one
# series over K = 1 .. 32 (points labelled with K), against the median construction time:
#   1. the largest tone error over the stroke images, relative to its tolerance max(0.25 %, 0.8 / N);
#   2. the largest coefficient of variation of the darkness over quarter-tile windows (images in the
#      uniformity scope of hatching/bake/quality.h; dashed: every stroke image), the 0.08 target marked;
#   3. the largest low-frequency power share (same scope; dashed: every image), the 3 % target marked.
# Usage: gnuplot -e "dir='build-bench/results'; resolutions='64 128 256 512'" bench/tam/plot.gp
# tam.csv: 1 candidates, 2 resolution, 3 seconds, 4 max_tone_error, 5 max_tone_error_over_tolerance,
#          6 max_cv, 7 max_low_frequency_power, 8 max_cv_all, 9 max_low_frequency_power_all, ...
if (!exists("dir")) dir = 'build-bench/results'
if (!exists("resolutions")) resolutions = '64 128 256 512'
set datafile separator ','
set terminal pngcairo size 1800,560 enhanced font ',10'
set output dir.'/tam.png'
set multiplot layout 1,3
set grid
set logscale x
set xlabel 'construction seconds (median)'
set key top right
rows(r) = sprintf("< awk -F, 'NR > 1 && $2 == %s' '%s/tam.csv'", r, dir)

set title 'tone error / tolerance (max over stroke images)'
set ylabel 'max |darkness - target| / tolerance'
set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead dt 3 lw 1.5 lc 'black'
plot for [k = 1:words(resolutions)] rows(word(resolutions, k)) using 3:5 with linespoints lc k pt 7 title word(resolutions, k).'^2', \
     for [k = 1:words(resolutions)] rows(word(resolutions, k)) using 3:5:(sprintf('%d', $1)) with labels offset char 0.8,0.6 textcolor lt k notitle
unset arrow 1

set title 'ink uniformity: CV over quarter-tile windows (solid: scoped images, dashed: all)'
set ylabel 'max coefficient of variation'
set logscale y
set arrow 1 from graph 0, first 0.08 to graph 1, first 0.08 nohead dt 3 lw 1.5 lc 'black'
plot for [k = 1:words(resolutions)] rows(word(resolutions, k)) using 3:($6 > 0 ? $6 : NaN) with linespoints lc k pt 7 title word(resolutions, k).'^2', \
     for [k = 1:words(resolutions)] rows(word(resolutions, k)) using 3:8 with linespoints lc k pt 6 dt 2 notitle, \
     for [k = 1:words(resolutions)] rows(word(resolutions, k)) using 3:($6 > 0 ? $6 : NaN):(sprintf('%d', $1)) with labels offset char 0.8,0.6 textcolor lt k notitle
unset arrow 1

set title 'low-frequency power share, below 4 cycles per tile (solid: scoped, dashed: all)'
set ylabel 'max share of non-DC power'
set arrow 1 from graph 0, first 0.03 to graph 1, first 0.03 nohead dt 3 lw 1.5 lc 'black'
plot for [k = 1:words(resolutions)] rows(word(resolutions, k)) using 3:($7 > 0 ? $7 : NaN) with linespoints lc k pt 7 title word(resolutions, k).'^2', \
     for [k = 1:words(resolutions)] rows(word(resolutions, k)) using 3:9 with linespoints lc k pt 6 dt 2 notitle
unset arrow 1
unset multiplot
