# paintstrokes.png: RMSE against the fine-tube reference over the polygons drawn, per stroke set
# (rows) and view (columns): paintstrokes at quality 0, 1, 2 over the subdivision tolerance, fixed
# tubes over sides x steps. Lower left is better. Called by run.sh with dir='...'.
set terminal pngcairo size 1800,1500 font "sans,10"
set output dir."/paintstrokes.png"
set datafile separator ","
set logscale xy
set grid
set key top right font ",9"
set multiplot layout 3,3 title "Paintstrokes (view-dependent tessellation) against fixed tubes: image RMSE vs polygons per frame"
sets = "curls tree fur"
views = "close mid far"
sel(s, v, m, q) = sprintf("< awk -F, '$1==\"%s\" && $2==\"%s\" && $3==\"%s\" && ($4==\"%s\" || \"%s\"==\"*\") && $11>0' '%s/paintstrokes.csv' | sort -t, -k8,8n", s, v, m, q, q, dir)
do for [i=1:3] {
  do for [j=1:3] {
    s = word(sets, i); v = word(views, j)
    set title s." / ".v
    set xlabel "polygons (triangles) per frame"
    set ylabel "RMSE (8-bit sRGB, 0..1)"
    plot sel(s, v, "paintstrokes", "0") using 8:11 with linespoints pt 7 title "paintstrokes q0", \
         sel(s, v, "paintstrokes", "1") using 8:11 with linespoints pt 5 lw 2 title "paintstrokes q1", \
         sel(s, v, "paintstrokes", "2") using 8:11 with linespoints pt 9 title "paintstrokes q2", \
         sel(s, v, "tubes", "*") using 8:11 with points pt 6 ps 1.2 title "fixed tubes (sides x steps)"
  }
}
unset multiplot
