# Digits of the truncation coefficient and of H_d: correct significant digits of c = T_h/(ω⁶h⁴q) (against its exact value, which tends to 1/1440) and of H_d over the run, against ωh, one panel per precision (each with its own digits axis)
# Redraw with: gnuplot truncation_digits.gp (in this directory)
set terminal svg size 1180,330 dynamic enhanced font 'Sans,12' background rgb 'white'
set output 'truncation_digits.svg'
set multiplot
set origin 0.0000,0.0000
set size 0.3390,1.0000
set title 'digits of c and H_d in double'
set xlabel 'ωh (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
unset key
set xrange [3.78131e-09:7.40484]
set xtics 1e2
set mxtics 1
set yrange [0:16.2]
plot 'truncation_digits.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'truncation_digits.dat' index 1 u 1:2 w lp pt 6 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'H_d', \
     'truncation_digits.dat' index 2 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'digits the precision carries'
set origin 0.3390,0.0000
set size 0.3390,1.0000
set title 'digits of c and H_d in mpfr:50'
set xlabel 'ωh (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
unset key
set xrange [3.78131e-09:7.40484]
set xtics 1e2
set mxtics 1
set yrange [0:54]
plot 'truncation_digits.dat' index 3 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'truncation_digits.dat' index 4 u 1:2 w lp pt 6 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'H_d', \
     'truncation_digits.dat' index 5 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'digits the precision carries'
set origin 0.6780,0
set size 0.3220,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.6880,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     NaN w lp pt 6 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'H_d', \
     NaN w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'digits the precision carries'
unset multiplot

unset output
reset
set terminal pngcairo size 1180,330 enhanced font 'Sans,12' background rgb 'white'
set output 'truncation_digits.png'
set multiplot
set origin 0.0000,0.0000
set size 0.3390,1.0000
set title 'digits of c and H_d in double'
set xlabel 'ωh (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
unset key
set xrange [3.78131e-09:7.40484]
set xtics 1e2
set mxtics 1
set yrange [0:16.2]
plot 'truncation_digits.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'truncation_digits.dat' index 1 u 1:2 w lp pt 6 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'H_d', \
     'truncation_digits.dat' index 2 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'digits the precision carries'
set origin 0.3390,0.0000
set size 0.3390,1.0000
set title 'digits of c and H_d in mpfr:50'
set xlabel 'ωh (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
unset key
set xrange [3.78131e-09:7.40484]
set xtics 1e2
set mxtics 1
set yrange [0:54]
plot 'truncation_digits.dat' index 3 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     'truncation_digits.dat' index 4 u 1:2 w lp pt 6 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'H_d', \
     'truncation_digits.dat' index 5 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'digits the precision carries'
set origin 0.6780,0
set size 0.3220,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.6880,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'c (truncation coefficient)', \
     NaN w lp pt 6 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'H_d', \
     NaN w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'digits the precision carries'
unset multiplot

unset output
