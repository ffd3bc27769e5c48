# The stiff springs' energies I₁, I₂, I₃ and their sum I against t ≤ 200, a reference and each method at one ωh: the energy passes from the first spring to the others on the slow time scale while I stays within O(1/ω) of 1
# Redraw with: gnuplot fpu_exchange.gp (in this directory)
set terminal svg size 1280,900 dynamic enhanced font 'Sans,12' background rgb 'white'
set output 'fpu_exchange.svg'
set multiplot
set origin 0.0000,0.6667
set size 0.3516,0.3333
set title 'reference: gauss-legendre-2, ωh = 0.1'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10:210]
set yrange [-0.0525253:1.10303]
plot 'fpu_exchange.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 1 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 2 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 3 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.3516,0.6667
set size 0.3516,0.3333
set title 'simpson, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.0525078:1.10266]
plot 'fpu_exchange.dat' index 4 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 5 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 6 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 7 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.0000,0.3333
set size 0.3516,0.3333
set title 'stormer-verlet, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.0836081:1.75577]
plot 'fpu_exchange.dat' index 8 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 9 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 10 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 11 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.3516,0.3333
set size 0.3516,0.3333
set title 'implicit-midpoint, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.052621:1.10504]
plot 'fpu_exchange.dat' index 12 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 13 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 14 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 15 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.0000,0.0000
set size 0.3516,0.3333
set title 'gauss-legendre-2, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.0532471:1.11819]
plot 'fpu_exchange.dat' index 16 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 17 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 18 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 19 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.3516,0.0000
set size 0.3516,0.3333
set title 'trigonometric, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.051572:1.08301]
plot 'fpu_exchange.dat' index 20 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 21 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 22 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 23 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
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
plot NaN w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     NaN w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     NaN w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     NaN w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
unset multiplot

unset output
reset
set terminal pngcairo size 1280,900 enhanced font 'Sans,12' background rgb 'white'
set output 'fpu_exchange.png'
set multiplot
set origin 0.0000,0.6667
set size 0.3516,0.3333
set title 'reference: gauss-legendre-2, ωh = 0.1'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10:210]
set yrange [-0.0525253:1.10303]
plot 'fpu_exchange.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 1 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 2 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 3 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.3516,0.6667
set size 0.3516,0.3333
set title 'simpson, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.0525078:1.10266]
plot 'fpu_exchange.dat' index 4 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 5 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 6 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 7 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.0000,0.3333
set size 0.3516,0.3333
set title 'stormer-verlet, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.0836081:1.75577]
plot 'fpu_exchange.dat' index 8 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 9 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 10 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 11 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.3516,0.3333
set size 0.3516,0.3333
set title 'implicit-midpoint, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.052621:1.10504]
plot 'fpu_exchange.dat' index 12 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 13 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 14 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 15 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.0000,0.0000
set size 0.3516,0.3333
set title 'gauss-legendre-2, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.0532471:1.11819]
plot 'fpu_exchange.dat' index 16 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 17 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 18 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 19 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
set origin 0.3516,0.0000
set size 0.3516,0.3333
set title 'trigonometric, ωh = 1.5'
set xlabel 't'
set ylabel 'oscillatory energy'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
unset key
set xrange [-10.0005:210.01]
set yrange [-0.051572:1.08301]
plot 'fpu_exchange.dat' index 20 u 1:2 w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     'fpu_exchange.dat' index 21 u 1:2 w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     'fpu_exchange.dat' index 22 u 1:2 w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     'fpu_exchange.dat' index 23 u 1:2 w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
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
plot NaN w l lw 2 dt 1 lc rgb '#ff7f0e' t 'I₁', \
     NaN w l lw 2 dt 1 lc rgb '#8c564b' t 'I₂', \
     NaN w l lw 2 dt 1 lc rgb '#e377c2' t 'I₃', \
     NaN w l lw 2 dt 1 lc rgb '#17becf' t 'I = I₁ + I₂ + I₃'
unset multiplot

unset output
