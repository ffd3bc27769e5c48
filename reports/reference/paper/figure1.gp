# Figure 1 redrawn: exact and computed p and q over one period, N = 15
# Redraw with: gnuplot figure1.gp (in this directory)
set terminal svg size 900,500 dynamic enhanced font 'Sans,12' background rgb 'white'
set output 'figure1.svg'
set title 'Figure 1: harmonic oscillator, one period, N = 15'
set xlabel 't (periods)'
set ylabel 'q and p/(mω) (dimensionless)'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
set key outside right
set xrange [-0.05:1.05]
set yrange [-1.1:1.1]
plot 'figure1.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#000000' t 'q exact', \
     'figure1.dat' index 1 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'p/(mω) exact', \
     'figure1.dat' index 2 u 1:2 w lp pt 6 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'q Newmark', \
     'figure1.dat' index 3 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'p/(mω) Newmark', \
     'figure1.dat' index 4 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'q Simpson', \
     'figure1.dat' index 5 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'p/(mω) Simpson'

unset output
reset
set terminal pngcairo size 900,500 enhanced font 'Sans,12' background rgb 'white'
set output 'figure1.png'
set title 'Figure 1: harmonic oscillator, one period, N = 15'
set xlabel 't (periods)'
set ylabel 'q and p/(mω) (dimensionless)'
unset logscale x
set format x '%g'
unset logscale y
set format y '%g'
set key outside right
set xrange [-0.05:1.05]
set yrange [-1.1:1.1]
plot 'figure1.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#000000' t 'q exact', \
     'figure1.dat' index 1 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'p/(mω) exact', \
     'figure1.dat' index 2 u 1:2 w lp pt 6 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'q Newmark', \
     'figure1.dat' index 3 u 1:2 w lp pt 4 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'p/(mω) Newmark', \
     'figure1.dat' index 4 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'q Simpson', \
     'figure1.dat' index 5 u 1:2 w lp pt 5 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'p/(mω) Simpson'

unset output
