# Table 1: maximum errors of p and q against N, ours (lines) and published (open points), with slopes h² and h⁴ (dashed guides)
# Redraw with: gnuplot table1_convergence.gp (in this directory)
set terminal svg size 900,500 dynamic enhanced font 'Sans,12' background rgb 'white'
set output 'table1_convergence.svg'
set title 'Table 1: maximum errors against N (one period)'
set xlabel 'N (steps per period)'
set ylabel 'maximum error: |Δp| (absolute, m = 1) and |Δq|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key outside right
set xrange [9.12011:43.8591]
set format x '%g'
set xtics (10, 20, 40)
set mxtics default
set yrange [7.90129e-07:3.84593]
set ytics 1e2
set mytics 1
plot 'table1_convergence.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'Newmark p ours', \
     'table1_convergence.dat' index 1 u 1:2 w p pt 6 ps 1.6 lc rgb '#1f77b4' t 'Newmark p paper', \
     'table1_convergence.dat' index 2 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'Simpson p ours', \
     'table1_convergence.dat' index 3 u 1:2 w p pt 6 ps 1.6 lc rgb '#d62728' t 'Simpson p paper', \
     'table1_convergence.dat' index 4 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#2ca02c' t 'Newmark q ours', \
     'table1_convergence.dat' index 5 u 1:2 w p pt 6 ps 1.6 lc rgb '#2ca02c' t 'Newmark q paper', \
     'table1_convergence.dat' index 6 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#9467bd' t 'Simpson q ours', \
     'table1_convergence.dat' index 7 u 1:2 w p pt 6 ps 1.6 lc rgb '#9467bd' t 'Simpson q paper', \
     'table1_convergence.dat' index 8 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope h^2', \
     'table1_convergence.dat' index 9 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope h^4'

unset output
reset
set terminal pngcairo size 900,500 enhanced font 'Sans,12' background rgb 'white'
set output 'table1_convergence.png'
set title 'Table 1: maximum errors against N (one period)'
set xlabel 'N (steps per period)'
set ylabel 'maximum error: |Δp| (absolute, m = 1) and |Δq|'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key outside right
set xrange [9.12011:43.8591]
set format x '%g'
set xtics (10, 20, 40)
set mxtics default
set yrange [7.90129e-07:3.84593]
set ytics 1e2
set mytics 1
plot 'table1_convergence.dat' index 0 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#1f77b4' t 'Newmark p ours', \
     'table1_convergence.dat' index 1 u 1:2 w p pt 6 ps 1.6 lc rgb '#1f77b4' t 'Newmark p paper', \
     'table1_convergence.dat' index 2 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#d62728' t 'Simpson p ours', \
     'table1_convergence.dat' index 3 u 1:2 w p pt 6 ps 1.6 lc rgb '#d62728' t 'Simpson p paper', \
     'table1_convergence.dat' index 4 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#2ca02c' t 'Newmark q ours', \
     'table1_convergence.dat' index 5 u 1:2 w p pt 6 ps 1.6 lc rgb '#2ca02c' t 'Newmark q paper', \
     'table1_convergence.dat' index 6 u 1:2 w lp pt 7 ps 0.8 lw 1.2 dt 1 lc rgb '#9467bd' t 'Simpson q ours', \
     'table1_convergence.dat' index 7 u 1:2 w p pt 6 ps 1.6 lc rgb '#9467bd' t 'Simpson q paper', \
     'table1_convergence.dat' index 8 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope h^2', \
     'table1_convergence.dat' index 9 u 1:2 w l lw 1.5 dt 2 lc rgb '#000000' t 'slope h^4'

unset output
