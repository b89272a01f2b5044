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
# Methods with at least one plottable point per source count (run.sh finds them); all by default.
if (!exists("methods1")) methods1 = 'exact heat fmm cgal-exact cgal-heat'
if (!exists("methods8")) methods8 = methods1
# Exact methods agree to rounding (~1e-16): lift them to a floor so that they show on the plot.
floor = 1e-5
error_of(m, s) = (strcol(4) eq m && column(5) == s && strcol(12) eq 'ok' && strcol(8) ne '') ? \
              (column(8) > floor ? column(8) : floor) : NaN
seconds_of(m, s) = (strcol(4) eq m && column(5) == s && strcol(12) eq 'ok') ? column(6) + column(7) : NaN
set multiplot layout 1,2
all = 'exact heat fmm cgal-exact cgal-heat'
point(m) = 4 + 2 * words(substr(all, 1, strstrt(all, m)))
do for [s in '1 8'] {
  methods = s eq '1' ? methods1 : methods8
  set title sprintf('%s source(s); exact methods drawn at %g', s, floor)
  if (strlen(methods) > 0) {
    plot for [m in methods] csv using (seconds_of(m, s + 0)):(error_of(m, s + 0)) skip 1 \
         with points pt point(m) ps 1.2 title m
  } else {
    set label 1 'no errors measured' at graph 0.5, 0.5 center
    plot [1e-3:1] [1e-3:1] NaN notitle
    unset label 1
  }
}
unset multiplot
