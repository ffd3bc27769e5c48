# Maximum error of q and p/(mω) against run time (log-log; the median of the timed runs, their minimum and maximum in timing.md), each scheme by its general step, what it runs for any force: Simpson's nonlinear step with its Newton solve, the implicit peers' stage equations (their matrix factored once for this linear force), the explicit peers' stages. As its own 2 × 2 matrix every scheme costs the same per step, so that form is drawn against N only (work_precision_n). The last panel is the highest precision of the run.
# Redraw with: gnuplot work_precision_time.gp (in this directory)
set terminal svg size 1380,440 dynamic enhanced font 'Sans,13' background rgb 'white'
set output 'work_precision_time.svg'
set multiplot
set origin 0.0000,0.0000
set size 0.3623,1.0000
set title 'double, each scheme by its general step'
set xlabel 'run time (s, median of repeats)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [1.49385e-07:0.000268152]
set xtics autofreq
set mxtics default
set yrange [2.94139e-15:0.34373]
set ytics 1e3
set mytics 1
plot 'work_precision_time.dat' index 0 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_time.dat' index 1 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_time.dat' index 2 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_time.dat' index 3 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_time.dat' index 4 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_time.dat' index 5 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_time.dat' index 6 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.3623,0.0000
set size 0.3623,1.0000
set title 'mpfr:100, each scheme by its general step'
set xlabel 'run time (s, median of repeats)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [7.4917e-06:0.0501633]
set xtics autofreq
set mxtics default
set yrange [3.33375e-15:0.341687]
set ytics 1e3
set mytics 1
plot 'work_precision_time.dat' index 7 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_time.dat' index 8 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_time.dat' index 9 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_time.dat' index 10 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_time.dat' index 11 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_time.dat' index 12 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_time.dat' index 13 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.7246,0
set size 0.2754,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.7346,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     NaN w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     NaN w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     NaN w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     NaN w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     NaN w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
unset multiplot

unset output
reset
set terminal pngcairo size 1380,440 enhanced font 'Sans,13' background rgb 'white'
set output 'work_precision_time.png'
set multiplot
set origin 0.0000,0.0000
set size 0.3623,1.0000
set title 'double, each scheme by its general step'
set xlabel 'run time (s, median of repeats)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [1.49385e-07:0.000268152]
set xtics autofreq
set mxtics default
set yrange [2.94139e-15:0.34373]
set ytics 1e3
set mytics 1
plot 'work_precision_time.dat' index 0 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_time.dat' index 1 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_time.dat' index 2 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_time.dat' index 3 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_time.dat' index 4 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_time.dat' index 5 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_time.dat' index 6 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.3623,0.0000
set size 0.3623,1.0000
set title 'mpfr:100, each scheme by its general step'
set xlabel 'run time (s, median of repeats)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [7.4917e-06:0.0501633]
set xtics autofreq
set mxtics default
set yrange [3.33375e-15:0.341687]
set ytics 1e3
set mytics 1
plot 'work_precision_time.dat' index 7 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_time.dat' index 8 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_time.dat' index 9 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_time.dat' index 10 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_time.dat' index 11 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_time.dat' index 12 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_time.dat' index 13 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
set origin 0.7246,0
set size 0.2754,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.7346,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     NaN w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     NaN w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     NaN w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     NaN w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     NaN w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4'
unset multiplot

unset output
