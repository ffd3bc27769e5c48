# Per-window maximum relative energy change against time (log-log)
# Redraw with: gnuplot long_time_energy.gp (in this directory)
set terminal svg size 1100,450 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'long_time_energy.svg'
set multiplot layout 1,2
set title 'Energy drift, double'
set xlabel 't (units of 1/omega)'
set ylabel 'per-window max |E - E_0|/E_0'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom right font ',8'
set yrange [4.42574e-12:0.518097]
plot 'long_time_energy.dat' index 0 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson-H_d', \
     'long_time_energy.dat' index 1 u 1:2 w l lw 1.5 lc rgb '#1f77b4' t 'newmark-H', \
     'long_time_energy.dat' index 2 u 1:2 w l lw 1.5 lc rgb '#17becf' t 'rk4-H'
set title 'Energy drift, mpfr:50'
set xlabel 't (units of 1/omega)'
set ylabel 'per-window max |E - E_0|/E_0'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom right font ',8'
set yrange [4.85107e-49:0.00554476]
plot 'long_time_energy.dat' index 3 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson-H_d', \
     'long_time_energy.dat' index 4 u 1:2 w l lw 1.5 lc rgb '#1f77b4' t 'newmark-H', \
     'long_time_energy.dat' index 5 u 1:2 w l lw 1.5 lc rgb '#17becf' t 'rk4-H'
unset multiplot

unset output
reset
set terminal pngcairo size 1100,450 enhanced font 'Sans,10' background rgb 'white'
set output 'long_time_energy.png'
set multiplot layout 1,2
set title 'Energy drift, double'
set xlabel 't (units of 1/omega)'
set ylabel 'per-window max |E - E_0|/E_0'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom right font ',8'
set yrange [4.42574e-12:0.518097]
plot 'long_time_energy.dat' index 0 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson-H_d', \
     'long_time_energy.dat' index 1 u 1:2 w l lw 1.5 lc rgb '#1f77b4' t 'newmark-H', \
     'long_time_energy.dat' index 2 u 1:2 w l lw 1.5 lc rgb '#17becf' t 'rk4-H'
set title 'Energy drift, mpfr:50'
set xlabel 't (units of 1/omega)'
set ylabel 'per-window max |E - E_0|/E_0'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom right font ',8'
set yrange [4.85107e-49:0.00554476]
plot 'long_time_energy.dat' index 3 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson-H_d', \
     'long_time_energy.dat' index 4 u 1:2 w l lw 1.5 lc rgb '#1f77b4' t 'newmark-H', \
     'long_time_energy.dat' index 5 u 1:2 w l lw 1.5 lc rgb '#17becf' t 'rk4-H'
unset multiplot

unset output
