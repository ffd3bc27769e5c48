# Maximum error of q and p/(mω) against N, one panel per precision; dashed guides: slopes N⁻² (grey) and N⁻⁴ (black); short dashes: the round-off floor 100 N eps
# Redraw with: gnuplot work_precision_n.gp (in this directory)
set terminal svg size 1760,800 dynamic enhanced font 'Sans,15' background rgb 'white'
set output 'work_precision_n.svg'
set multiplot
set origin 0.0000,0.5000
set size 0.2614,0.5000
set title 'double'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [4.29802e-15:0.337578]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 0 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 1 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 2 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 3 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 4 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 5 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 6 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 7 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 8 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 9 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 10 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.2614,0.5000
set size 0.2614,0.5000
set title 'long double'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [3.30045e-15:0.34185]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 11 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 12 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 13 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 14 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 15 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 16 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 17 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 18 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 19 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 20 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 21 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.5227,0.5000
set size 0.2614,0.5000
set title 'float128'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [3.33375e-15:0.341687]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 22 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 23 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 24 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 25 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 26 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 27 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 28 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 29 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 30 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 31 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 32 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.0000,0.0000
set size 0.2614,0.5000
set title 'mpfr:50'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [3.33375e-15:0.341687]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 33 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 34 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 35 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 36 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 37 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 38 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 39 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 40 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 41 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 42 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 43 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.2614,0.0000
set size 0.2614,0.5000
set title 'mpfr:100'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [3.33375e-15:0.341687]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 44 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 45 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 46 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 47 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 48 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 49 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 50 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 51 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 52 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 53 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 54 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.7841,0
set size 0.2159,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.7941,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     NaN w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     NaN w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     NaN w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     NaN w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     NaN w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     NaN w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     NaN w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     NaN w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     NaN w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
unset multiplot

unset output
reset
set terminal pngcairo size 1760,800 enhanced font 'Sans,15' background rgb 'white'
set output 'work_precision_n.png'
set multiplot
set origin 0.0000,0.5000
set size 0.2614,0.5000
set title 'double'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [4.29802e-15:0.337578]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 0 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 1 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 2 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 3 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 4 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 5 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 6 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 7 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 8 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 9 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 10 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.2614,0.5000
set size 0.2614,0.5000
set title 'long double'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [3.30045e-15:0.34185]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 11 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 12 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 13 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 14 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 15 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 16 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 17 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 18 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 19 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 20 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 21 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.5227,0.5000
set size 0.2614,0.5000
set title 'float128'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [3.33375e-15:0.341687]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 22 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 23 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 24 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 25 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 26 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 27 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 28 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 29 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 30 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 31 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 32 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.0000,0.0000
set size 0.2614,0.5000
set title 'mpfr:50'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [3.33375e-15:0.341687]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 33 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 34 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 35 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 36 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 37 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 38 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 39 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 40 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 41 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 42 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 43 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.2614,0.0000
set size 0.2614,0.5000
set title 'mpfr:100'
set xlabel 'N (steps per period)'
set ylabel 'max error of q and p/(mω)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [12.1257:5404.7]
set xtics autofreq
set mxtics default
set yrange [3.33375e-15:0.341687]
set ytics 1e3
set mytics 1
plot 'work_precision_n.dat' index 44 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'work_precision_n.dat' index 45 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'work_precision_n.dat' index 46 u 1:2 w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     'work_precision_n.dat' index 47 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'work_precision_n.dat' index 48 u 1:2 w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'work_precision_n.dat' index 49 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'work_precision_n.dat' index 50 u 1:2 w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     'work_precision_n.dat' index 51 u 1:2 w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     'work_precision_n.dat' index 52 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     'work_precision_n.dat' index 53 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     'work_precision_n.dat' index 54 u 1:2 w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
set origin 0.7841,0
set size 0.2159,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.7941,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     NaN w lp pt 9 ps 0.8 lw 1.2 dt 3 lc rgb '#2ca02c' t 'simpson-elimination', \
     NaN w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     NaN w lp pt 13 ps 0.8 lw 1.2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     NaN w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     NaN w p pt 6 ps 1.6 lc rgb '#e377c2' t 'lobatto-iiia-iiib-3', \
     NaN w lp pt 8 ps 0.8 lw 1.2 dt 4 lc rgb '#17becf' t 'rk4', \
     NaN w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope N^{-2}', \
     NaN w l lw 1.5 dt 2 lc rgb '#000000' t 'slope N^{-4}', \
     NaN w l lw 1.5 dt 3 lc rgb '#7f7f7f' t 'round-off floor 100 N eps'
unset multiplot

unset output
