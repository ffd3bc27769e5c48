# Relative energy error |H − H(0)|/H(0) (solid) and |I − I(0)| (dashed) against t, a panel per method, a colour per ωh; a run that became unstable ends where it stopped
# Redraw with: gnuplot fpu_errors.gp (in this directory)
set terminal svg size 1280,620 dynamic enhanced font 'Sans,12' background rgb 'white'
set output 'fpu_errors.svg'
set multiplot
set origin 0.0000,0.6667
set size 0.3516,0.3333
set title 'simpson'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.51:10499.5]
set yrange [1.85613e-08:10.0327]
set ytics 1e2
set mytics 1
plot 'fpu_errors.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 1 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 2 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 3 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     'fpu_errors.dat' index 4 u 1:2 w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     'fpu_errors.dat' index 5 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I'
set origin 0.3516,0.6667
set size 0.3516,0.3333
set title 'stormer-verlet'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.51:10499.5]
set yrange [9.5873e-07:1.24743]
set ytics autofreq
set mytics default
plot 'fpu_errors.dat' index 6 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 7 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 8 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 9 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I'
set origin 0.0000,0.3333
set size 0.3516,0.3333
set title 'implicit-midpoint'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.543:10499.5]
set yrange [2.54247e-08:0.150939]
set ytics 1e2
set mytics 1
plot 'fpu_errors.dat' index 10 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 11 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 12 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 13 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     'fpu_errors.dat' index 14 u 1:2 w l lw 2 dt 1 lc rgb '#2ca02c' t 'ωh = 3: H', \
     'fpu_errors.dat' index 15 u 1:2 w l lw 2 dt 2 lc rgb '#2ca02c' t 'ωh = 3: I', \
     'fpu_errors.dat' index 16 u 1:2 w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     'fpu_errors.dat' index 17 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I'
set origin 0.3516,0.3333
set size 0.3516,0.3333
set title 'gauss-legendre-2'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.543:10499.5]
set yrange [1.61321e-10:0.194191]
set ytics 1e2
set mytics 1
plot 'fpu_errors.dat' index 18 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 19 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 20 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 21 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     'fpu_errors.dat' index 22 u 1:2 w l lw 2 dt 1 lc rgb '#2ca02c' t 'ωh = 3: H', \
     'fpu_errors.dat' index 23 u 1:2 w l lw 2 dt 2 lc rgb '#2ca02c' t 'ωh = 3: I', \
     'fpu_errors.dat' index 24 u 1:2 w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     'fpu_errors.dat' index 25 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I'
set origin 0.0000,0.0000
set size 0.3516,0.3333
set title 'trigonometric'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.543:10499.5]
set yrange [5.95568e-09:0.132516]
set ytics 1e2
set mytics 1
plot 'fpu_errors.dat' index 26 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 27 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 28 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 29 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     'fpu_errors.dat' index 30 u 1:2 w l lw 2 dt 1 lc rgb '#2ca02c' t 'ωh = 3: H', \
     'fpu_errors.dat' index 31 u 1:2 w l lw 2 dt 2 lc rgb '#2ca02c' t 'ωh = 3: I', \
     'fpu_errors.dat' index 32 u 1:2 w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     'fpu_errors.dat' index 33 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I'
set origin 0.7031,0
set size 0.2969,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.7131,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     NaN w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     NaN w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     NaN w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     NaN w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     NaN w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I', \
     NaN w l lw 2 dt 1 lc rgb '#2ca02c' t 'ωh = 3: H', \
     NaN w l lw 2 dt 2 lc rgb '#2ca02c' t 'ωh = 3: I'
unset multiplot

unset output
reset
set terminal pngcairo size 1280,620 enhanced font 'Sans,12' background rgb 'white'
set output 'fpu_errors.png'
set multiplot
set origin 0.0000,0.6667
set size 0.3516,0.3333
set title 'simpson'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.51:10499.5]
set yrange [1.85613e-08:10.0327]
set ytics 1e2
set mytics 1
plot 'fpu_errors.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 1 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 2 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 3 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     'fpu_errors.dat' index 4 u 1:2 w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     'fpu_errors.dat' index 5 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I'
set origin 0.3516,0.6667
set size 0.3516,0.3333
set title 'stormer-verlet'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.51:10499.5]
set yrange [9.5873e-07:1.24743]
set ytics autofreq
set mytics default
plot 'fpu_errors.dat' index 6 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 7 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 8 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 9 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I'
set origin 0.0000,0.3333
set size 0.3516,0.3333
set title 'implicit-midpoint'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.543:10499.5]
set yrange [2.54247e-08:0.150939]
set ytics 1e2
set mytics 1
plot 'fpu_errors.dat' index 10 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 11 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 12 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 13 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     'fpu_errors.dat' index 14 u 1:2 w l lw 2 dt 1 lc rgb '#2ca02c' t 'ωh = 3: H', \
     'fpu_errors.dat' index 15 u 1:2 w l lw 2 dt 2 lc rgb '#2ca02c' t 'ωh = 3: I', \
     'fpu_errors.dat' index 16 u 1:2 w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     'fpu_errors.dat' index 17 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I'
set origin 0.3516,0.3333
set size 0.3516,0.3333
set title 'gauss-legendre-2'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.543:10499.5]
set yrange [1.61321e-10:0.194191]
set ytics 1e2
set mytics 1
plot 'fpu_errors.dat' index 18 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 19 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 20 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 21 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     'fpu_errors.dat' index 22 u 1:2 w l lw 2 dt 1 lc rgb '#2ca02c' t 'ωh = 3: H', \
     'fpu_errors.dat' index 23 u 1:2 w l lw 2 dt 2 lc rgb '#2ca02c' t 'ωh = 3: I', \
     'fpu_errors.dat' index 24 u 1:2 w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     'fpu_errors.dat' index 25 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I'
set origin 0.0000,0.0000
set size 0.3516,0.3333
set title 'trigonometric'
set xlabel 't'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-489.543:10499.5]
set yrange [5.95568e-09:0.132516]
set ytics 1e2
set mytics 1
plot 'fpu_errors.dat' index 26 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     'fpu_errors.dat' index 27 u 1:2 w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     'fpu_errors.dat' index 28 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     'fpu_errors.dat' index 29 u 1:2 w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     'fpu_errors.dat' index 30 u 1:2 w l lw 2 dt 1 lc rgb '#2ca02c' t 'ωh = 3: H', \
     'fpu_errors.dat' index 31 u 1:2 w l lw 2 dt 2 lc rgb '#2ca02c' t 'ωh = 3: I', \
     'fpu_errors.dat' index 32 u 1:2 w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     'fpu_errors.dat' index 33 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I'
set origin 0.7031,0
set size 0.2969,1
unset title
unset xlabel
unset ylabel
unset logscale xy
unset border
unset tics
set xrange [0:1]
set yrange [0:1]
set key at screen 0.7131,0.97 left top Left reverse samplen 3 spacing 1.3
plot NaN w l lw 2 dt 1 lc rgb '#1f77b4' t 'ωh = 0.5: H', \
     NaN w l lw 2 dt 2 lc rgb '#1f77b4' t 'ωh = 0.5: I', \
     NaN w l lw 2 dt 1 lc rgb '#d62728' t 'ωh = 1.5: H', \
     NaN w l lw 2 dt 2 lc rgb '#d62728' t 'ωh = 1.5: I', \
     NaN w l lw 2 dt 1 lc rgb '#9467bd' t 'ωh = 4: H', \
     NaN w l lw 2 dt 2 lc rgb '#9467bd' t 'ωh = 4: I', \
     NaN w l lw 2 dt 1 lc rgb '#2ca02c' t 'ωh = 3: H', \
     NaN w l lw 2 dt 2 lc rgb '#2ca02c' t 'ωh = 3: I'
unset multiplot

unset output
