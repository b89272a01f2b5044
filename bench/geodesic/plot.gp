# Error against time for every method, log-log, one panel per source count, one series per method.
# Usage: gnuplot -e "csv='results/geodesic.csv'; png='results/geodesic.png'" bench/geodesic/plot.gp
# Columns: 1 mesh, 2 triangles, 3 vertices, 4 method, 5 sources, 6 seconds, 7 setup_seconds,
# 8 mean_rel_error, 9 max_rel_error, 10 reference, 11 runs, 12 status. The time is one field plus the
# once-per-mesh setup (the heat methods' factorisation), i.e. the cost of the first field.
if (!exists("csv")) csv = 'build-bench/results/geodesic.csv'
if (!exists("png")) png = 'build-bench/results/geodesic.png'
set datafile separator ','
set terminal pngcairo size 1400,600 enhanced font ',10'
set output png
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'seconds (setup + one field)'
set ylabel 'mean |error| / max distance'
set key bottom left
set grid
methods = 'exact heat fmm cgal-exact cgal-heat'
# Exact methods agree to rounding (~1e-16): lift them to a floor so that they show on the plot.
floor = 1e-5
error_of(m, s) = (strcol(4) eq m && column(5) == s && strcol(12) eq 'ok' && strcol(8) ne '') ? \
              (column(8) > floor ? column(8) : floor) : NaN
seconds_of(m, s) = (strcol(4) eq m && column(5) == s && strcol(12) eq 'ok') ? column(6) + column(7) : NaN
set multiplot layout 1,2
do for [s in '1 8'] {
  set title sprintf('%s source(s); exact methods drawn at %g', s, floor)
  plot for [m in methods] csv using (seconds_of(m, s + 0)):(error_of(m, s + 0)) skip 1 with points pt (4 + 2 * words(substr(methods, 1, strstrt(methods, m)))) ps 1.2 title m
}
unset multiplot
