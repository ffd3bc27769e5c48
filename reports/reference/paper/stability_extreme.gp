# Correct digits of the truncation coefficient (solid) and of H_d (dashed) against ωh, per precision
# Redraw with: gnuplot stability_extreme.gp (in this directory)
set terminal svg size 800,500 dynamic enhanced font 'Sans,10' background rgb 'white'
set output 'stability_extreme.svg'
set title 'Digits kept against omega h'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
set key outside right
names = 'double long-double float128 mpfr:50 mpfr:100'
n = words(names)
plot for [i=0:4] 'stability_extreme.dat' index i u 1:2 w lp lc i+1 pt 7 t 'c: '.word(names, i+1), for [i=0:4] '' index i u 1:3 w lp dt 2 lc i+1 pt 6 t 'H_d: '.word(names, i+1)

unset output
reset
set terminal pngcairo size 800,500 enhanced font 'Sans,10' background rgb 'white'
set output 'stability_extreme.png'
set title 'Digits kept against omega h'
set xlabel 'omega h (dimensionless)'
set ylabel 'correct significant digits'
set logscale x
set format x '10^{%L}'
set key outside right
names = 'double long-double float128 mpfr:50 mpfr:100'
n = words(names)
plot for [i=0:4] 'stability_extreme.dat' index i u 1:2 w lp lc i+1 pt 7 t 'c: '.word(names, i+1), for [i=0:4] '' index i u 1:3 w lp dt 2 lc i+1 pt 6 t 'H_d: '.word(names, i+1)

unset output
