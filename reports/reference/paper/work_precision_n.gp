# Maximum error against N, one panel per precision; dashed: the round-off floor 100 N eps
# Redraw with: gnuplot work_precision_n.gp (in this directory)
set terminal svg size 1260,680 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'work_precision_n.svg'
names = 'newmark simpson simpson-elimination stormer-verlet yoshida gauss-legendre-2 lobatto-iiia-iiib-3 rk4'
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set key bottom left font ',8'
set multiplot layout 2,3
set format x '%g'
set title 'double'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_double.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*2.22e-16 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
set title 'long double'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_long-double.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*1.08e-19 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
set title 'float128'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_float128.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*1.93e-34 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
set title 'mpfr:50'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_mpfr50.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*5.35e-51 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
set title 'mpfr:100'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_mpfr100.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*5.71e-101 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
unset multiplot

unset output
reset
set terminal pngcairo size 1260,680 enhanced font 'Sans,10' background rgb 'white'
set output 'work_precision_n.png'
names = 'newmark simpson simpson-elimination stormer-verlet yoshida gauss-legendre-2 lobatto-iiia-iiib-3 rk4'
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set key bottom left font ',8'
set multiplot layout 2,3
set format x '%g'
set title 'double'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_double.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*2.22e-16 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
set title 'long double'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_long-double.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*1.08e-19 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
set title 'float128'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_float128.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*1.93e-34 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
set title 'mpfr:50'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_mpfr50.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*5.35e-51 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
set title 'mpfr:100'
set xlabel 'N (steps per period)'
set ylabel 'max error'
plot for [i=0:7] 'work_precision_mpfr100.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), 100*x*5.71e-101 w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'
unset multiplot

unset output
