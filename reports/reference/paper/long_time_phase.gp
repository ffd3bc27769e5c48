# |Phase error| against time (log-log), measured (solid) and predicted by the characteristic roots (dashed)
# Redraw with: gnuplot long_time_phase.gp (in this directory)
set terminal svg size 1100,450 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'long_time_phase.svg'
set multiplot layout 1,2
set title 'Phase error, double'
set xlabel 't (units of 1/omega)'
set ylabel '|phase error| (rad)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key top left font ',8'
set yrange [8.68188e-05:3328.34]
plot 'long_time_phase.dat' index 0 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson-H_d measured', \
     'long_time_phase.dat' index 1 u 1:2 w l dt 2 lc rgb '#d62728' t 'simpson-H_d predicted', \
     'long_time_phase.dat' index 2 u 1:2 w l lw 1.5 lc rgb '#1f77b4' t 'newmark-H measured', \
     'long_time_phase.dat' index 3 u 1:2 w l dt 2 lc rgb '#1f77b4' t 'newmark-H predicted', \
     'long_time_phase.dat' index 4 u 1:2 w l lw 1.5 lc rgb '#17becf' t 'rk4-H measured', \
     'long_time_phase.dat' index 5 u 1:2 w l dt 2 lc rgb '#17becf' t 'rk4-H predicted'
set title 'Phase error, mpfr:50'
set xlabel 't (units of 1/omega)'
set ylabel '|phase error| (rad)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key top left font ',8'
set yrange [8.68314e-07:33.2834]
plot 'long_time_phase.dat' index 6 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson-H_d measured', \
     'long_time_phase.dat' index 7 u 1:2 w l dt 2 lc rgb '#d62728' t 'simpson-H_d predicted', \
     'long_time_phase.dat' index 8 u 1:2 w l lw 1.5 lc rgb '#1f77b4' t 'newmark-H measured', \
     'long_time_phase.dat' index 9 u 1:2 w l dt 2 lc rgb '#1f77b4' t 'newmark-H predicted', \
     'long_time_phase.dat' index 10 u 1:2 w l lw 1.5 lc rgb '#17becf' t 'rk4-H measured', \
     'long_time_phase.dat' index 11 u 1:2 w l dt 2 lc rgb '#17becf' t 'rk4-H predicted'
unset multiplot

unset output
reset
set terminal pngcairo size 1100,450 enhanced font 'Sans,10' background rgb 'white'
set output 'long_time_phase.png'
set multiplot layout 1,2
set title 'Phase error, double'
set xlabel 't (units of 1/omega)'
set ylabel '|phase error| (rad)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key top left font ',8'
set yrange [8.68188e-05:3328.34]
plot 'long_time_phase.dat' index 0 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson-H_d measured', \
     'long_time_phase.dat' index 1 u 1:2 w l dt 2 lc rgb '#d62728' t 'simpson-H_d predicted', \
     'long_time_phase.dat' index 2 u 1:2 w l lw 1.5 lc rgb '#1f77b4' t 'newmark-H measured', \
     'long_time_phase.dat' index 3 u 1:2 w l dt 2 lc rgb '#1f77b4' t 'newmark-H predicted', \
     'long_time_phase.dat' index 4 u 1:2 w l lw 1.5 lc rgb '#17becf' t 'rk4-H measured', \
     'long_time_phase.dat' index 5 u 1:2 w l dt 2 lc rgb '#17becf' t 'rk4-H predicted'
set title 'Phase error, mpfr:50'
set xlabel 't (units of 1/omega)'
set ylabel '|phase error| (rad)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key top left font ',8'
set yrange [8.68314e-07:33.2834]
plot 'long_time_phase.dat' index 6 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson-H_d measured', \
     'long_time_phase.dat' index 7 u 1:2 w l dt 2 lc rgb '#d62728' t 'simpson-H_d predicted', \
     'long_time_phase.dat' index 8 u 1:2 w l lw 1.5 lc rgb '#1f77b4' t 'newmark-H measured', \
     'long_time_phase.dat' index 9 u 1:2 w l dt 2 lc rgb '#1f77b4' t 'newmark-H predicted', \
     'long_time_phase.dat' index 10 u 1:2 w l lw 1.5 lc rgb '#17becf' t 'rk4-H measured', \
     'long_time_phase.dat' index 11 u 1:2 w l dt 2 lc rgb '#17becf' t 'rk4-H predicted'
unset multiplot

unset output
