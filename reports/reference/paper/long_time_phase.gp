# Phase error against time, measured (solid) and predicted by the characteristic roots (dashed)
# Redraw with: gnuplot long_time_phase.gp (in this directory)
set terminal svg size 1100,450 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'long_time_phase.svg'
names = 'Simpson-H_d Newmark-H RK4-H'
set multiplot layout 1,2
set logscale x
set format x '10^{%L}'
set xlabel 't (units of 1/omega)'
set ylabel 'phase error (rad)'
set key top left
set title 'Phase error, double'
plot for [i=0:2] 'long_time_double.dat' index i u 1:3 w l lc i+1 t word(names, i+1).' measured', for [i=0:2] '' index i u 1:4 w l dt 2 lc i+1 t word(names, i+1).' predicted'
set title 'Phase error, mpfr50'
plot for [i=0:2] 'long_time_mpfr50.dat' index i u 1:3 w l lc i+1 t word(names, i+1).' measured', for [i=0:2] '' index i u 1:4 w l dt 2 lc i+1 t word(names, i+1).' predicted'
unset multiplot

unset output
reset
set terminal pngcairo size 1100,450 enhanced font 'Sans,10' background rgb 'white'
set output 'long_time_phase.png'
names = 'Simpson-H_d Newmark-H RK4-H'
set multiplot layout 1,2
set logscale x
set format x '10^{%L}'
set xlabel 't (units of 1/omega)'
set ylabel 'phase error (rad)'
set key top left
set title 'Phase error, double'
plot for [i=0:2] 'long_time_double.dat' index i u 1:3 w l lc i+1 t word(names, i+1).' measured', for [i=0:2] '' index i u 1:4 w l dt 2 lc i+1 t word(names, i+1).' predicted'
set title 'Phase error, mpfr50'
plot for [i=0:2] 'long_time_mpfr50.dat' index i u 1:3 w l lc i+1 t word(names, i+1).' measured', for [i=0:2] '' index i u 1:4 w l dt 2 lc i+1 t word(names, i+1).' predicted'
unset multiplot

unset output
