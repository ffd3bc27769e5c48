# |Phase error| against time (log-log), measured (markers) and predicted by the characteristic roots (lines)
# Redraw with: gnuplot long_time_phase.gp (in this directory)
set terminal svg size 1480,450 dynamic enhanced font 'Sans,13' background rgb 'white'
set output 'long_time_phase.svg'
set multiplot
set origin 0.0000,0.0000
set size 0.3716,1.0000
set title 'Phase error, double'
set xlabel 't (units of 1/ω)'
set ylabel '|phase error| (rad)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [7943.28:1.25893e+06]
set xtics autofreq
set mxtics default
set yrange [0.000166609:1734.37]
set ytics 1e2
set mytics 1
plot 'long_time_phase.dat' index 0 u 1:2 w p pt 7 ps 1.6 lc rgb '#d62728' t 'simpson measured', \
     'long_time_phase.dat' index 1 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson predicted', \
     'long_time_phase.dat' index 2 u 1:2 w p pt 5 ps 1.6 lc rgb '#1f77b4' t 'newmark measured', \
     'long_time_phase.dat' index 3 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark predicted', \
     'long_time_phase.dat' index 4 u 1:2 w p pt 8 ps 1.6 lc rgb '#17becf' t 'rk4 measured', \
     'long_time_phase.dat' index 5 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'rk4 predicted'
set origin 0.3716,0.0000
set size 0.3716,1.0000
set title 'Phase error, mpfr:50'
set xlabel 't (units of 1/ω)'
set ylabel '|phase error| (rad)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [79.4328:12589.3]
set xtics autofreq
set mxtics default
set yrange [1.66635e-06:17.3436]
set ytics 1e2
set mytics 1
plot 'long_time_phase.dat' index 6 u 1:2 w p pt 7 ps 1.6 lc rgb '#d62728' t 'simpson measured', \
     'long_time_phase.dat' index 7 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson predicted', \
     'long_time_phase.dat' index 8 u 1:2 w p pt 5 ps 1.6 lc rgb '#1f77b4' t 'newmark measured', \
     'long_time_phase.dat' index 9 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark predicted', \
     'long_time_phase.dat' index 10 u 1:2 w p pt 8 ps 1.6 lc rgb '#17becf' t 'rk4 measured', \
     'long_time_phase.dat' index 11 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'rk4 predicted'
set origin 0.7432,0
set size 0.2568,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.7532,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w p pt 7 ps 1.6 lc rgb '#d62728' t 'simpson measured', \
     NaN w l lw 2 dt 1 lc rgb '#d62728' t 'simpson predicted', \
     NaN w p pt 5 ps 1.6 lc rgb '#1f77b4' t 'newmark measured', \
     NaN w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark predicted', \
     NaN w p pt 8 ps 1.6 lc rgb '#17becf' t 'rk4 measured', \
     NaN w l lw 2 dt 1 lc rgb '#17becf' t 'rk4 predicted'
unset multiplot

unset output
reset
set terminal pngcairo size 1480,450 enhanced font 'Sans,13' background rgb 'white'
set output 'long_time_phase.png'
set multiplot
set origin 0.0000,0.0000
set size 0.3716,1.0000
set title 'Phase error, double'
set xlabel 't (units of 1/ω)'
set ylabel '|phase error| (rad)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [7943.28:1.25893e+06]
set xtics autofreq
set mxtics default
set yrange [0.000166609:1734.37]
set ytics 1e2
set mytics 1
plot 'long_time_phase.dat' index 0 u 1:2 w p pt 7 ps 1.6 lc rgb '#d62728' t 'simpson measured', \
     'long_time_phase.dat' index 1 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson predicted', \
     'long_time_phase.dat' index 2 u 1:2 w p pt 5 ps 1.6 lc rgb '#1f77b4' t 'newmark measured', \
     'long_time_phase.dat' index 3 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark predicted', \
     'long_time_phase.dat' index 4 u 1:2 w p pt 8 ps 1.6 lc rgb '#17becf' t 'rk4 measured', \
     'long_time_phase.dat' index 5 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'rk4 predicted'
set origin 0.3716,0.0000
set size 0.3716,1.0000
set title 'Phase error, mpfr:50'
set xlabel 't (units of 1/ω)'
set ylabel '|phase error| (rad)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [79.4328:12589.3]
set xtics autofreq
set mxtics default
set yrange [1.66635e-06:17.3436]
set ytics 1e2
set mytics 1
plot 'long_time_phase.dat' index 6 u 1:2 w p pt 7 ps 1.6 lc rgb '#d62728' t 'simpson measured', \
     'long_time_phase.dat' index 7 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson predicted', \
     'long_time_phase.dat' index 8 u 1:2 w p pt 5 ps 1.6 lc rgb '#1f77b4' t 'newmark measured', \
     'long_time_phase.dat' index 9 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark predicted', \
     'long_time_phase.dat' index 10 u 1:2 w p pt 8 ps 1.6 lc rgb '#17becf' t 'rk4 measured', \
     'long_time_phase.dat' index 11 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'rk4 predicted'
set origin 0.7432,0
set size 0.2568,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.7532,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w p pt 7 ps 1.6 lc rgb '#d62728' t 'simpson measured', \
     NaN w l lw 2 dt 1 lc rgb '#d62728' t 'simpson predicted', \
     NaN w p pt 5 ps 1.6 lc rgb '#1f77b4' t 'newmark measured', \
     NaN w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark predicted', \
     NaN w p pt 8 ps 1.6 lc rgb '#17becf' t 'rk4 measured', \
     NaN w l lw 2 dt 1 lc rgb '#17becf' t 'rk4 predicted'
unset multiplot

unset output
