# The largest relative errors in H and in I over t ≤ 100 against the stiff springs' ωh, each method; a method's unstable runs are left out (the scan table has them); grey circles: runs at a step-size resonance. The x tics mark Φ₃'s band ends.
# Redraw with: gnuplot fpu_scan.gp (in this directory)
set terminal svg size 1380,420 dynamic enhanced font 'Sans,13' background rgb 'white'
set output 'fpu_scan.svg'
set multiplot
set origin 0.0000,0.0000
set size 0.3623,1.0000
set title 'max |H − H(0)|/H(0)'
set xlabel 'ωh of the stiff springs'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-0.145:5.245]
set yrange [1.2118e-10:41.7585]
set ytics 1e2
set mytics 1
set xtics ('2√2' 2.82843, '2√3' 3.4641, '2√6' 4.89898, '0' 0, '1' 1, '2' 2)
set mxtics 1
plot 'fpu_scan.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'fpu_scan.dat' index 1 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'fpu_scan.dat' index 2 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'fpu_scan.dat' index 3 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'implicit-midpoint', \
     'fpu_scan.dat' index 4 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'fpu_scan.dat' index 5 u 1:2 w lp pt 12 ps 0.8 lw 1.2 dt 1 lc rgb '#000000' t 'trigonometric', \
     'fpu_scan.dat' index 6 u 1:2 w p pt 6 ps 1.6 lc rgb '#7f7f7f' t 'resonance θ = 2π/k'
set origin 0.3623,0.0000
set size 0.3623,1.0000
set xtics autofreq
set ytics autofreq
set mxtics default
set mytics default
set title 'max |I − I(0)|/I(0)'
set xlabel 'ωh of the stiff springs'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-0.145:5.245]
set yrange [5.41102e-05:46.7637]
set ytics autofreq
set mytics default
set xtics ('2√2' 2.82843, '2√3' 3.4641, '2√6' 4.89898, '0' 0, '1' 1, '2' 2)
set mxtics 1
plot 'fpu_scan.dat' index 7 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'fpu_scan.dat' index 8 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'fpu_scan.dat' index 9 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'fpu_scan.dat' index 10 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'implicit-midpoint', \
     'fpu_scan.dat' index 11 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'fpu_scan.dat' index 12 u 1:2 w lp pt 12 ps 0.8 lw 1.2 dt 1 lc rgb '#000000' t 'trigonometric', \
     'fpu_scan.dat' index 13 u 1:2 w p pt 6 ps 1.6 lc rgb '#7f7f7f' t 'resonance θ = 2π/k'
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
plot NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     NaN w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     NaN w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'implicit-midpoint', \
     NaN w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     NaN w lp pt 12 ps 0.8 lw 1.2 dt 1 lc rgb '#000000' t 'trigonometric', \
     NaN w p pt 6 ps 1.6 lc rgb '#7f7f7f' t 'resonance θ = 2π/k'
unset multiplot

unset output
reset
set terminal pngcairo size 1380,420 enhanced font 'Sans,13' background rgb 'white'
set output 'fpu_scan.png'
set multiplot
set origin 0.0000,0.0000
set size 0.3623,1.0000
set title 'max |H − H(0)|/H(0)'
set xlabel 'ωh of the stiff springs'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-0.145:5.245]
set yrange [1.2118e-10:41.7585]
set ytics 1e2
set mytics 1
set xtics ('2√2' 2.82843, '2√3' 3.4641, '2√6' 4.89898, '0' 0, '1' 1, '2' 2)
set mxtics 1
plot 'fpu_scan.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'fpu_scan.dat' index 1 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'fpu_scan.dat' index 2 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'fpu_scan.dat' index 3 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'implicit-midpoint', \
     'fpu_scan.dat' index 4 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'fpu_scan.dat' index 5 u 1:2 w lp pt 12 ps 0.8 lw 1.2 dt 1 lc rgb '#000000' t 'trigonometric', \
     'fpu_scan.dat' index 6 u 1:2 w p pt 6 ps 1.6 lc rgb '#7f7f7f' t 'resonance θ = 2π/k'
set origin 0.3623,0.0000
set size 0.3623,1.0000
set xtics autofreq
set ytics autofreq
set mxtics default
set mytics default
set title 'max |I − I(0)|/I(0)'
set xlabel 'ωh of the stiff springs'
set ylabel 'relative error'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
unset key
set xrange [-0.145:5.245]
set yrange [5.41102e-05:46.7637]
set ytics autofreq
set mytics default
set xtics ('2√2' 2.82843, '2√3' 3.4641, '2√6' 4.89898, '0' 0, '1' 1, '2' 2)
set mxtics 1
plot 'fpu_scan.dat' index 7 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'fpu_scan.dat' index 8 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     'fpu_scan.dat' index 9 u 1:2 w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'fpu_scan.dat' index 10 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'implicit-midpoint', \
     'fpu_scan.dat' index 11 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'fpu_scan.dat' index 12 u 1:2 w lp pt 12 ps 0.8 lw 1.2 dt 1 lc rgb '#000000' t 'trigonometric', \
     'fpu_scan.dat' index 13 u 1:2 w p pt 6 ps 1.6 lc rgb '#7f7f7f' t 'resonance θ = 2π/k'
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
plot NaN w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'simpson', \
     NaN w lp pt 11 ps 0.8 lw 1.2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     NaN w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'implicit-midpoint', \
     NaN w lp pt 4 ps 0.8 lw 1.2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     NaN w lp pt 12 ps 0.8 lw 1.2 dt 1 lc rgb '#000000' t 'trigonometric', \
     NaN w p pt 6 ps 1.6 lc rgb '#7f7f7f' t 'resonance θ = 2π/k'
unset multiplot

unset output
