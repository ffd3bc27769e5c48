# Per-window maximum relative energy change against time (log-log)
# Redraw with: gnuplot long_time_energy.gp (in this directory)
set terminal svg size 1100,450 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'long_time_energy.svg'
names = 'Simpson-H_d Newmark-H RK4-H'
set multiplot layout 1,2
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set xlabel 't (units of 1/omega)'
set ylabel 'per-window max |E - E_0|/E_0'
set key bottom right
set title 'Energy drift, double'
plot for [i=0:2] 'long_time_double.dat' index i u 1:($2 > 0 ? $2 : NaN) w l lc i+1 t word(names, i+1)
set title 'Energy drift, mpfr50'
plot for [i=0:2] 'long_time_mpfr50.dat' index i u 1:($2 > 0 ? $2 : NaN) w l lc i+1 t word(names, i+1)
unset multiplot

unset output
reset
set terminal pngcairo size 1100,450 enhanced font 'Sans,10' background rgb 'white'
set output 'long_time_energy.png'
names = 'Simpson-H_d Newmark-H RK4-H'
set multiplot layout 1,2
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set xlabel 't (units of 1/omega)'
set ylabel 'per-window max |E - E_0|/E_0'
set key bottom right
set title 'Energy drift, double'
plot for [i=0:2] 'long_time_double.dat' index i u 1:($2 > 0 ? $2 : NaN) w l lc i+1 t word(names, i+1)
set title 'Energy drift, mpfr50'
plot for [i=0:2] 'long_time_mpfr50.dat' index i u 1:($2 > 0 ? $2 : NaN) w l lc i+1 t word(names, i+1)
unset multiplot

unset output
