# Spectral radius ρ(Φ) of each scheme's one-step matrix on the oscillator against ωh (m = ω = 1, computed in double). Φ₃ (simpson, the same matrix as Lobatto IIIA–IIIB and the elimination route) has ρ = 1 on its exact stable set (0, 2 sqrt(2)) ∪ (2 sqrt(3), 2 sqrt(6)) and ρ > 1 in the gap and beyond; the x tics mark its band ends. Curves on ρ = 1 lie on one another. The first ωh of the grid (step 0.005) where ρ exceeds 1 + 10⁻⁹: newmark nowhere; simpson at 2.830; stormer-verlet at 2.005; yoshida at 1.575; gauss-legendre-2 nowhere; rk4 at 2.830. RK4 lies below 1 before it: it damps.
# Redraw with: gnuplot stability_spectral_radius.gp (in this directory)
set terminal svg size 900,520 dynamic enhanced font 'Sans,12' background rgb 'white'
set output 'stability_spectral_radius.svg'
set title 'spectral radius of each scheme''s one-step matrix'
set xlabel 'ωh (dimensionless)'
set ylabel 'ρ(Φ) = max |λ|'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
set key top left
set xrange [-0.34475:7.34975]
set yrange [0.298234:25801.2]
set ytics autofreq
set mytics default
set xtics ('2√2' 2.82843, '2√3' 3.4641, '2√6' 4.89898, '0' 0, '1' 1, '2' 2, '6' 6, '7' 7)
set mxtics 1
plot 'stability_spectral_radius.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'stability_spectral_radius.dat' index 1 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson', \
     'stability_spectral_radius.dat' index 2 u 1:2 w l lw 2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'stability_spectral_radius.dat' index 3 u 1:2 w l lw 2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'stability_spectral_radius.dat' index 4 u 1:2 w l lw 2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'stability_spectral_radius.dat' index 5 u 1:2 w l lw 2 dt 4 lc rgb '#17becf' t 'rk4', \
     'stability_spectral_radius.dat' index 6 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'ρ = 1'

unset output
reset
set terminal pngcairo size 900,520 enhanced font 'Sans,12' background rgb 'white'
set output 'stability_spectral_radius.png'
set title 'spectral radius of each scheme''s one-step matrix'
set xlabel 'ωh (dimensionless)'
set ylabel 'ρ(Φ) = max |λ|'
unset logscale x
set format x '%g'
set logscale y
set format y '10^{%L}'
set key top left
set xrange [-0.34475:7.34975]
set yrange [0.298234:25801.2]
set ytics autofreq
set mytics default
set xtics ('2√2' 2.82843, '2√3' 3.4641, '2√6' 4.89898, '0' 0, '1' 1, '2' 2, '6' 6, '7' 7)
set mxtics 1
plot 'stability_spectral_radius.dat' index 0 u 1:2 w l lw 2 dt 1 lc rgb '#1f77b4' t 'newmark', \
     'stability_spectral_radius.dat' index 1 u 1:2 w l lw 2 dt 1 lc rgb '#d62728' t 'simpson', \
     'stability_spectral_radius.dat' index 2 u 1:2 w l lw 2 dt 4 lc rgb '#9467bd' t 'stormer-verlet', \
     'stability_spectral_radius.dat' index 3 u 1:2 w l lw 2 dt 5 lc rgb '#ff7f0e' t 'yoshida', \
     'stability_spectral_radius.dat' index 4 u 1:2 w l lw 2 dt 2 lc rgb '#8c564b' t 'gauss-legendre-2', \
     'stability_spectral_radius.dat' index 5 u 1:2 w l lw 2 dt 4 lc rgb '#17becf' t 'rk4', \
     'stability_spectral_radius.dat' index 6 u 1:2 w l lw 1.5 dt 2 lc rgb '#7f7f7f' t 'ρ = 1'

unset output
