# Maximum error against N, one panel per precision; dashed: the round-off floor 100 N eps
# Redraw with: gnuplot work_precision_n.gp (in this directory)
set terminal svg size 1320,720 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'work_precision_n.svg'
set multiplot layout 2,3
set title 'double'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [4.60049e-15:0.315383]
plot 'work_precision_n.dat' index 0 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 1 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 2 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 3 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 4 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 5 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 6 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 7 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 8 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set title 'long double'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [3.57742e-15:0.315383]
plot 'work_precision_n.dat' index 9 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 10 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 11 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 12 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 13 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 14 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 15 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 16 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 17 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set title 'float128'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [3.61179e-15:0.315383]
plot 'work_precision_n.dat' index 18 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 19 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 20 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 21 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 22 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 23 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 24 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 25 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 26 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set title 'mpfr:50'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [3.61179e-15:0.315383]
plot 'work_precision_n.dat' index 27 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 28 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 29 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 30 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 31 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 32 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 33 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 34 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 35 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set title 'mpfr:100'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [3.61179e-15:0.315383]
plot 'work_precision_n.dat' index 36 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 37 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 38 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 39 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 40 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 41 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 42 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 43 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 44 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
unset multiplot

unset output
reset
set terminal pngcairo size 1320,720 enhanced font 'Sans,10' background rgb 'white'
set output 'work_precision_n.png'
set multiplot layout 2,3
set title 'double'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [4.60049e-15:0.315383]
plot 'work_precision_n.dat' index 0 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 1 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 2 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 3 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 4 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 5 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 6 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 7 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 8 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set title 'long double'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [3.57742e-15:0.315383]
plot 'work_precision_n.dat' index 9 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 10 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 11 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 12 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 13 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 14 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 15 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 16 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 17 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set title 'float128'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [3.61179e-15:0.315383]
plot 'work_precision_n.dat' index 18 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 19 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 20 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 21 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 22 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 23 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 24 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 25 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 26 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set title 'mpfr:50'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [3.61179e-15:0.315383]
plot 'work_precision_n.dat' index 27 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 28 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 29 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 30 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 31 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 32 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 33 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 34 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 35 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set title 'mpfr:100'
set xlabel 'N (steps per period)'
set ylabel 'max error'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key bottom left font ',8'
set yrange [3.61179e-15:0.315383]
plot 'work_precision_n.dat' index 36 u 1:2 w lp pt 5 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 37 u 1:2 w l lw 1.5 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 38 u 1:2 w lp pt 9 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 39 u 1:2 w lp pt 11 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 40 u 1:2 w lp pt 13 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 41 u 1:2 w lp pt 4 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 42 u 1:2 w p pt 6 ps 1.5 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 43 u 1:2 w lp pt 8 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 44 u 1:2 w l dt 2 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
unset multiplot

unset output
