# Table 1: maximum errors of p and q against N, ours (lines) and published (open points)
# Redraw with: gnuplot table1_convergence.gp (in this directory)
set terminal svg size 800,500 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'table1_convergence.svg'
set title 'Table 1: maximum errors against N (one period)'
set xlabel 'N (steps per period)'
set ylabel 'maximum error (p in m omega units, q dimensionless)'
set logscale xy
set format y '10^{%L}'
set key outside right
names = 'Newmark-p Simpson-p Newmark-q Simpson-q'
plot for [i=0:3] 'table1_convergence.dat' index i u 1:2 w lp lc i+1 pt 7 t word(names, i+1).' ours', for [i=0:3] '' index i u 1:3 w p lc i+1 pt 6 ps 2 t word(names, i+1).' paper'

unset output
reset
set terminal pngcairo size 800,500 enhanced font 'Sans,10' background rgb 'white'
set output 'table1_convergence.png'
set title 'Table 1: maximum errors against N (one period)'
set xlabel 'N (steps per period)'
set ylabel 'maximum error (p in m omega units, q dimensionless)'
set logscale xy
set format y '10^{%L}'
set key outside right
names = 'Newmark-p Simpson-p Newmark-q Simpson-q'
plot for [i=0:3] 'table1_convergence.dat' index i u 1:2 w lp lc i+1 pt 7 t word(names, i+1).' ours', for [i=0:3] '' index i u 1:3 w p lc i+1 pt 6 ps 2 t word(names, i+1).' paper'

unset output
