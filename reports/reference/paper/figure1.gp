# Figure 1 redrawn: exact and computed p and q over one period, N = 15
# Redraw with: gnuplot figure1.gp (in this directory)
set terminal svg size 800,500 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'figure1.svg'
set title 'Figure 1: harmonic oscillator, one period, N = 15'
set xlabel 't (periods)'
set ylabel 'q and p/(m omega) (dimensionless)'
set key outside right
plot 'figure1_exact.dat' u 1:2 w l lc rgb 'black' t 'q exact', '' u 1:3 w l dt 2 lc rgb 'black' t 'p/(m omega) exact', 'figure1_schemes.dat' u 1:2 w lp pt 6 lc rgb '#1f77b4' t 'q Newmark', '' u 1:3 w lp pt 4 lc rgb '#1f77b4' t 'p/(m omega) Newmark', '' u 1:4 w lp pt 7 lc rgb '#d62728' t 'q Simpson', '' u 1:5 w lp pt 5 lc rgb '#d62728' t 'p/(m omega) Simpson'

unset output
reset
set terminal pngcairo size 800,500 enhanced font 'Sans,10' background rgb 'white'
set output 'figure1.png'
set title 'Figure 1: harmonic oscillator, one period, N = 15'
set xlabel 't (periods)'
set ylabel 'q and p/(m omega) (dimensionless)'
set key outside right
plot 'figure1_exact.dat' u 1:2 w l lc rgb 'black' t 'q exact', '' u 1:3 w l dt 2 lc rgb 'black' t 'p/(m omega) exact', 'figure1_schemes.dat' u 1:2 w lp pt 6 lc rgb '#1f77b4' t 'q Newmark', '' u 1:3 w lp pt 4 lc rgb '#1f77b4' t 'p/(m omega) Newmark', '' u 1:4 w lp pt 7 lc rgb '#d62728' t 'q Simpson', '' u 1:5 w lp pt 5 lc rgb '#d62728' t 'p/(m omega) Simpson'

unset output
