# Table 1's entries (round-off rows left out): computed over printed under the stated conventions , under the simplest hypothesis and under the best fit; an entry is reproduced only within half a unit of its third digit (about ±0.05 to ±0.5%)
# Redraw with: gnuplot table1_search.gp (in this directory)
set terminal svg size 900,600 dynamic enhanced font 'Sans,12' background rgb 'white'
set output 'table1_search.svg'
set title 'Table 1: computed over printed, entry by entry'
set xlabel 'printed value'
set ylabel 'computed / printed'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right
set xrange [7.9483e-07:3.84485]
set xtics 1e2
set mxtics 1
set yrange [0:1.3]
plot 'table1_search.dat' index 0 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'reproduced: 1 (± half a unit of the last digit)', \
     'table1_search.dat' index 1 u 1:2 w p pt 6 ps 1.6 lc rgb '#1f77b4' t 'stated conventions', \
     'table1_search.dat' index 2 u 1:2 w p pt 5 ps 1.6 lc rgb '#2ca02c' t 'simplest: released from rest at q₀ = π/2, p₀ = 0, m = 1', \
     'table1_search.dat' index 3 u 1:2 w p pt 7 ps 1.6 lc rgb '#d62728' t 'best fit'

unset output
reset
set terminal pngcairo size 900,600 enhanced font 'Sans,12' background rgb 'white'
set output 'table1_search.png'
set title 'Table 1: computed over printed, entry by entry'
set xlabel 'printed value'
set ylabel 'computed / printed'
set logscale x
set format x '10^{%L}'
unset logscale y
set format y '%g'
set key bottom right
set xrange [7.9483e-07:3.84485]
set xtics 1e2
set mxtics 1
set yrange [0:1.3]
plot 'table1_search.dat' index 0 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'reproduced: 1 (± half a unit of the last digit)', \
     'table1_search.dat' index 1 u 1:2 w p pt 6 ps 1.6 lc rgb '#1f77b4' t 'stated conventions', \
     'table1_search.dat' index 2 u 1:2 w p pt 5 ps 1.6 lc rgb '#2ca02c' t 'simplest: released from rest at q₀ = π/2, p₀ = 0, m = 1', \
     'table1_search.dat' index 3 u 1:2 w p pt 7 ps 1.6 lc rgb '#d62728' t 'best fit'

unset output
