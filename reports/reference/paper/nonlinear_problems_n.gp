# Nonlinear problems in double: state error at T (top) and the largest relative energy error (bottom) against N, log-log
# Redraw with: gnuplot nonlinear_problems_n.gp (in this directory)
set terminal svg size 2580,720 dynamic enhanced font 'Sans,18' background rgb 'white'
set output 'nonlinear_problems_n.svg'
set multiplot
set origin 0.0000,0.5000
set size 0.1705,0.5000
set title 'oscillator: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [2.51598e-15:0.00942973]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 1 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 2 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 3 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 4 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.1705,0.5000
set size 0.1705,0.5000
set title 'pendulum: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [1.00325e-15:0.00120974]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 5 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 6 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 7 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 8 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 9 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.3411,0.5000
set size 0.1705,0.5000
set title 'kepler: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [519.842:50427.7]
set xtics autofreq
set mxtics default
set yrange [6.13271e-06:1193.17]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 10 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 11 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 12 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 13 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 14 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.5116,0.5000
set size 0.1705,0.5000
set title 'henon-heiles: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [1.74912e-12:0.238913]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 15 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 16 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 17 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 18 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 19 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.6822,0.5000
set size 0.1705,0.5000
set title 'fpu: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [1.31557e-10:0.114842]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 20 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 21 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 22 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 23 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 24 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.0000,0.0000
set size 0.1705,0.5000
set title 'oscillator: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [1.2584e-16:0.0103638]
set ytics 1e3
set mytics 1
plot 'nonlinear_problems_n.dat' index 25 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 26 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 27 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 28 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 29 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.1705,0.0000
set size 0.1705,0.5000
set title 'pendulum: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [9.11518e-15:0.020522]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 30 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 31 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 32 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 33 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 34 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.3411,0.0000
set size 0.1705,0.5000
set title 'kepler: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [519.842:50427.7]
set xtics autofreq
set mxtics default
set yrange [8.09932e-08:189.158]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 35 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 36 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 37 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 38 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 39 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.5116,0.0000
set size 0.1705,0.5000
set title 'henon-heiles: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [4.66508e-13:0.0951183]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 40 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 41 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 42 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 43 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 44 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.6822,0.0000
set size 0.1705,0.5000
set title 'fpu: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [2.74938e-13:73.4153]
set ytics 1e3
set mytics 1
plot 'nonlinear_problems_n.dat' index 45 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 46 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 47 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 48 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 49 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
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
set terminal pngcairo size 2580,720 enhanced font 'Sans,18' background rgb 'white'
set output 'nonlinear_problems_n.png'
set multiplot
set origin 0.0000,0.5000
set size 0.1705,0.5000
set title 'oscillator: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [2.51598e-15:0.00942973]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 1 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 2 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 3 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 4 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.1705,0.5000
set size 0.1705,0.5000
set title 'pendulum: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [1.00325e-15:0.00120974]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 5 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 6 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 7 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 8 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 9 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.3411,0.5000
set size 0.1705,0.5000
set title 'kepler: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [519.842:50427.7]
set xtics autofreq
set mxtics default
set yrange [6.13271e-06:1193.17]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 10 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 11 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 12 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 13 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 14 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.5116,0.5000
set size 0.1705,0.5000
set title 'henon-heiles: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [1.74912e-12:0.238913]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 15 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 16 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 17 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 18 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 19 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.6822,0.5000
set size 0.1705,0.5000
set title 'fpu: state error'
set xlabel 'N'
set ylabel '|q_N - q(T)|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [1.31557e-10:0.114842]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 20 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 21 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 22 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 23 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 24 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.0000,0.0000
set size 0.1705,0.5000
set title 'oscillator: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [1.2584e-16:0.0103638]
set ytics 1e3
set mytics 1
plot 'nonlinear_problems_n.dat' index 25 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 26 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 27 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 28 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 29 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.1705,0.0000
set size 0.1705,0.5000
set title 'pendulum: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [9.11518e-15:0.020522]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 30 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 31 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 32 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 33 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 34 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.3411,0.0000
set size 0.1705,0.5000
set title 'kepler: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [519.842:50427.7]
set xtics autofreq
set mxtics default
set yrange [8.09932e-08:189.158]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 35 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 36 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 37 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 38 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 39 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.5116,0.0000
set size 0.1705,0.5000
set title 'henon-heiles: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [4.66508e-13:0.0951183]
set ytics 1e2
set mytics 1
plot 'nonlinear_problems_n.dat' index 40 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 41 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 42 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 43 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 44 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.6822,0.0000
set size 0.1705,0.5000
set title 'fpu: energy error'
set xlabel 'N'
set ylabel 'max |H - H_0|/|H_0|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [51.9842:5042.77]
set xtics autofreq
set mxtics default
set yrange [2.74938e-13:73.4153]
set ytics 1e3
set mytics 1
plot 'nonlinear_problems_n.dat' index 45 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'nonlinear_problems_n.dat' index 46 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'nonlinear_problems_n.dat' index 47 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'nonlinear_problems_n.dat' index 48 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'nonlinear_problems_n.dat' index 49 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
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
