# groove-bake.png: groovebake's median wall time against the groove count (left), and the cell size
# sweep on the largest scene: bake time and mean references per cell against the stored geometry's
# largest error (right). Called by run.sh with dir='...'.
set terminal pngcairo size 1200,500
set output dir.'/groove-bake.png'
set datafile separator ','
set multiplot layout 1,2
set logscale xy
set grid
set key top left
set title 'groovebake: median bake time'
set xlabel 'grooves'
set ylabel 'seconds'
plot dir.'/groove-bake.csv' using 1:3 every ::1 with linespoints title 'wall', \
     '' using 1:4 every ::1 with linespoints title 'CPU (all threads)', \
     2 with lines dashtype 2 title '2 s target'
set title 'cell size sweep (largest scene)'
set xlabel 'cell size / automatic'
set ylabel 'seconds, references per cell'
set y2label 'max stored position error'
set y2tics
set logscale y2
plot dir.'/cell-size.csv' using 1:3 every ::1 with linespoints title 'wall s', \
     '' using 1:5 every ::1 with linespoints title 'mean refs / cell', \
     '' using 1:8 every ::1 axes x1y2 with linespoints title 'max position error (right)'
unset multiplot
