# Nonlinear problems in double: state error at T against run time (log-log)
# Redraw with: gnuplot nonlinear_problems_time.gp (in this directory)
set terminal svg size 2580,380 dynamic enhanced font 'Sans,18' background rgb 'white'
set output 'nonlinear_problems_time.svg'
set multiplot
set origin 0.0000,0.0000
set size 0.1705,1.0000
set title 'oscillator'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [4.57705e-06:0.00735616]
set xtics autofreq
set mxtics default
set yrange [2.51598e-15:0.00942973]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 1 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 2 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 3 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 4 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.1705,0.0000
set size 0.1705,1.0000
set title 'pendulum'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [4.86441e-06:0.00765683]
set xtics autofreq
set mxtics default
set yrange [1.00325e-15:0.00120974]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 5 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 6 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 7 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 8 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 9 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.3411,0.0000
set size 0.1705,1.0000
set title 'kepler'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [4.82229e-05:0.10523]
set xtics autofreq
set mxtics default
set yrange [6.13271e-06:1193.17]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 10 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 11 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 12 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 13 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 14 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.5116,0.0000
set size 0.1705,1.0000
set title 'henon-heiles'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [4.52154e-06:0.00815232]
set xtics autofreq
set mxtics default
set yrange [1.74912e-12:0.238913]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 15 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 16 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 17 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 18 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 19 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.6822,0.0000
set size 0.1705,1.0000
set title 'fpu'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [7.26132e-06:0.0180162]
set xtics autofreq
set mxtics default
set yrange [1.31557e-10:0.114842]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 20 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 21 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 22 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 23 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 24 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.8527,0
set size 0.1473,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.8627,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     NaN w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     NaN w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     NaN w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     NaN w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
unset multiplot

unset output
reset
set terminal pngcairo size 2580,380 enhanced font 'Sans,18' background rgb 'white'
set output 'nonlinear_problems_time.png'
set multiplot
set origin 0.0000,0.0000
set size 0.1705,1.0000
set title 'oscillator'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [4.57705e-06:0.00735616]
set xtics autofreq
set mxtics default
set yrange [2.51598e-15:0.00942973]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 1 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 2 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 3 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 4 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.1705,0.0000
set size 0.1705,1.0000
set title 'pendulum'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [4.86441e-06:0.00765683]
set xtics autofreq
set mxtics default
set yrange [1.00325e-15:0.00120974]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 5 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 6 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 7 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 8 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 9 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.3411,0.0000
set size 0.1705,1.0000
set title 'kepler'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [4.82229e-05:0.10523]
set xtics autofreq
set mxtics default
set yrange [6.13271e-06:1193.17]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 10 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 11 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 12 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 13 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 14 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.5116,0.0000
set size 0.1705,1.0000
set title 'henon-heiles'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [4.52154e-06:0.00815232]
set xtics autofreq
set mxtics default
set yrange [1.74912e-12:0.238913]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 15 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 16 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 17 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 18 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 19 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.6822,0.0000
set size 0.1705,1.0000
set title 'fpu'
set xlabel 'run time (s, median of repeats)'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [7.26132e-06:0.0180162]
set xtics autofreq
set mxtics default
set yrange [1.31557e-10:0.114842]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_time.dat' index 20 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_time.dat' index 21 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_time.dat' index 22 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_time.dat' index 23 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_time.dat' index 24 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.8527,0
set size 0.1473,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.8627,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     NaN w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     NaN w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     NaN w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     NaN w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
unset multiplot

unset output
