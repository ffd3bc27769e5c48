# Maximum error against run time (log-log), one panel per precision
# Redraw with: gnuplot work_precision_time.gp (in this directory)
set terminal svg size 1260,680 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'work_precision_time.svg'
names = 'newmark simpson simpson-elimination stormer-verlet yoshida gauss-legendre-2 lobatto-iiia-iiib-3 rk4'
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set key bottom left font ',8'
set multiplot layout 2,3
set title 'double'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_double.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
set title 'long double'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_long-double.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
set title 'float128'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_float128.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
set title 'mpfr:50'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_mpfr50.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
set title 'mpfr:100'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_mpfr100.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
unset multiplot

unset output
reset
set terminal pngcairo size 1260,680 enhanced font 'Sans,10' background rgb 'white'
set output 'work_precision_time.png'
names = 'newmark simpson simpson-elimination stormer-verlet yoshida gauss-legendre-2 lobatto-iiia-iiib-3 rk4'
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set key bottom left font ',8'
set multiplot layout 2,3
set title 'double'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_double.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
set title 'long double'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_long-double.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
set title 'float128'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_float128.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
set title 'mpfr:50'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_mpfr50.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
set title 'mpfr:100'
set xlabel 'run time (s, minimum of repeats)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_mpfr100.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)
unset multiplot

unset output
