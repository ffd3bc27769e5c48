# Correct significant digits of the truncation coefficient c and of H_d against ωh, one panel per precision (each with its own digits axis)
# Redraw with: gnuplot stability_extreme.gp (in this directory)
set terminal svg size 1200,660 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'stability_extreme.svg'
set multiplot layout 2,3
set title 'double'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [-0.735:15.435]
plot 'stability_extreme.dat' index 0 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 1 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
set title 'long double'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [-0.9:18.9]
plot 'stability_extreme.dat' index 2 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 3 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
set title 'float128'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [-1.64:34.44]
plot 'stability_extreme.dat' index 4 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 5 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
set title 'mpfr:50'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [-2.485:52.185]
plot 'stability_extreme.dat' index 6 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 7 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
set title 'mpfr:100'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [46.815:101.485]
plot 'stability_extreme.dat' index 8 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 9 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
unset multiplot

unset output
reset
set terminal pngcairo size 1200,660 enhanced font 'Sans,10' background rgb 'white'
set output 'stability_extreme.png'
set multiplot layout 2,3
set title 'double'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [-0.735:15.435]
plot 'stability_extreme.dat' index 0 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 1 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
set title 'long double'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [-0.9:18.9]
plot 'stability_extreme.dat' index 2 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 3 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
set title 'float128'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [-1.64:34.44]
plot 'stability_extreme.dat' index 4 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 5 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
set title 'mpfr:50'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [-2.485:52.185]
plot 'stability_extreme.dat' index 6 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 7 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
set title 'mpfr:100'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right font ',8'
set yrange [46.815:101.485]
plot 'stability_extreme.dat' index 8 u 1:2 w lp pt 7 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'stability_extreme.dat' index 9 u 1:2 w lp pt 6 lc rgb '#d62728' t 'H_d'
unset multiplot

unset output
