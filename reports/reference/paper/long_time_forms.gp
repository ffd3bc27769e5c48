# Relative H_d error of Φ₃'s three forms in double against the step count (log-log), with guides of slope 1 (drift) and 1/2 (random walk)
# Redraw with: gnuplot long_time_forms.gp (in this directory)
set terminal svg size 800,500 dynamic enhanced font 'Sans,12' background rgb 'white'
set output 'long_time_forms.svg'
set title 'Relative H_d error, double'
set xlabel 'steps'
set ylabel 'running max |H_d - H_d(0)|/H_d(0)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key top left
set xrange [56.2341:1.77828e+07]
set xtics autofreq
set mxtics default
set yrange [9.92262e-17:4.9264e-09]
set ytics 1e2
set mytics 1
plot 'long_time_forms.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'matrix', \
     'long_time_forms.dat' index 1 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'shear', \
     'long_time_forms.dat' index 2 u 1:2 w l lw 2 dt 3 lc rgb '#ff7f0e' t 'shear-compensated', \
     'long_time_forms.dat' index 3 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope t', \
     'long_time_forms.dat' index 4 u 1:2 w l lw 1.5 dt 3 lc rgb '#000000' t 'slope √t'

unset output
reset
set terminal pngcairo size 800,500 enhanced font 'Sans,12' background rgb 'white'
set output 'long_time_forms.png'
set title 'Relative H_d error, double'
set xlabel 'steps'
set ylabel 'running max |H_d - H_d(0)|/H_d(0)'
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set key top left
set xrange [56.2341:1.77828e+07]
set xtics autofreq
set mxtics default
set yrange [9.92262e-17:4.9264e-09]
set ytics 1e2
set mytics 1
plot 'long_time_forms.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'matrix', \
     'long_time_forms.dat' index 1 u 1:2 w l lw 2 dt 2 lc rgb '#9467bd' t 'shear', \
     'long_time_forms.dat' index 2 u 1:2 w l lw 2 dt 3 lc rgb '#ff7f0e' t 'shear-compensated', \
     'long_time_forms.dat' index 3 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'slope t', \
     'long_time_forms.dat' index 4 u 1:2 w l lw 1.5 dt 3 lc rgb '#000000' t 'slope √t'

unset output
