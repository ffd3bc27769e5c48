# Per-window maximum relative energy change against time (log-log)
# Redraw with: gnuplot long_time_energy.gp (in this directory)
set terminal svg size 1480,450 dynamic enhanced font 'Sans,13' background rgb 'white'
set output 'long_time_energy.svg'
set multiplot
set origin 0.0000,0.0000
set size 0.3716,1.0000
set title 'Energy drift, double'
set xlabel 't (units of 1/ω)'
set ylabel 'per-window max |E - E_0|/E_0'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [7943.28:1.25893e+06]
set xtics autofreq
set mxtics default
set yrange [5.68631e-12:0.403242]
set ytics 1e2
set mytics 1
plot 'long_time_energy.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson-H_d', \
     'long_time_energy.dat' index 1 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark-H', \
     'long_time_energy.dat' index 2 u 1:2 w l lw 2 dt 4 lc rgb '#17becf' t 'rk4-H'
set origin 0.3716,0.0000
set size 0.3716,1.0000
set title 'Energy drift, mpfr:50'
set xlabel 't (units of 1/ω)'
set ylabel 'per-window max |E - E_0|/E_0'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [79.4328:12589.3]
set xtics autofreq
set mxtics default
set yrange [1.10883e-50:0.242402]
set ytics 1e8
set mytics 1
plot 'long_time_energy.dat' index 3 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson-H_d', \
     'long_time_energy.dat' index 4 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark-H', \
     'long_time_energy.dat' index 5 u 1:2 w l lw 2 dt 4 lc rgb '#17becf' t 'rk4-H'
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
plot NaN w l lw 2 dt 1 lc rgb '#d62728' t 'simpson-H_d', \
     NaN w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark-H', \
     NaN w l lw 2 dt 4 lc rgb '#17becf' t 'rk4-H'
unset multiplot

unset output
reset
set terminal pngcairo size 1480,450 enhanced font 'Sans,13' background rgb 'white'
set output 'long_time_energy.png'
set multiplot
set origin 0.0000,0.0000
set size 0.3716,1.0000
set title 'Energy drift, double'
set xlabel 't (units of 1/ω)'
set ylabel 'per-window max |E - E_0|/E_0'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [7943.28:1.25893e+06]
set xtics autofreq
set mxtics default
set yrange [5.68631e-12:0.403242]
set ytics 1e2
set mytics 1
plot 'long_time_energy.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson-H_d', \
     'long_time_energy.dat' index 1 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark-H', \
     'long_time_energy.dat' index 2 u 1:2 w l lw 2 dt 4 lc rgb '#17becf' t 'rk4-H'
set origin 0.3716,0.0000
set size 0.3716,1.0000
set title 'Energy drift, mpfr:50'
set xlabel 't (units of 1/ω)'
set ylabel 'per-window max |E - E_0|/E_0'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
unset key
set xrange [79.4328:12589.3]
set xtics autofreq
set mxtics default
set yrange [1.10883e-50:0.242402]
set ytics 1e8
set mytics 1
plot 'long_time_energy.dat' index 3 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson-H_d', \
     'long_time_energy.dat' index 4 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark-H', \
     'long_time_energy.dat' index 5 u 1:2 w l lw 2 dt 4 lc rgb '#17becf' t 'rk4-H'
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
plot NaN w l lw 2 dt 1 lc rgb '#d62728' t 'simpson-H_d', \
     NaN w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark-H', \
     NaN w l lw 2 dt 4 lc rgb '#17becf' t 'rk4-H'
unset multiplot

unset output
