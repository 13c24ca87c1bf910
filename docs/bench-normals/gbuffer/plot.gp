set terminal pngcairo size 1300,560 font 'DejaVu Sans,10'
set output 'error_vs_time.png'
set multiplot layout 1,2 title 'SSAO accuracy against CPU time (standard view, scene radius; mean over the scenes, one run)'
set logscale x
set grid
set key bottom right
set xlabel 'CPU time relative to the textbook pass'
set ylabel 'PSNR against ray-traced V_R (dB, higher is better)'
set title 'against the truth'
set arrow from graph 0, first 31.576 to graph 1, first 31.576 nohead dt 2 lw 2 lc rgb '#228833'
set label 'depth-only limit' at graph 0.02, first 31.976 tc rgb '#228833'
set yrange [*:33.076]
plot 'bench.dat' using ($4==0 ? $1 : 1/0):2 with points pt 7 ps 0.8 lc rgb '#4477aa' title 'kernel', \
     'bench.dat' using ($4==1 ? $1 : 1/0):2 with points pt 7 ps 0.8 lc rgb '#ee7733' title 'visibility', \
     'bench.dat' using ($4==3 ? $1 : 1/0):2 with points pt 4 ps 1.5 lc rgb '#777777' title 'presets 1.0', \
     'bench.dat' using ($4==2 ? $1 : 1/0):2 with points pt 9 ps 2 lc rgb '#aa3377' title 'presets', \
     'bench.dat' using ($4==4 ? $1 : 1/0):2 with points pt 5 ps 2 lc rgb '#000000' title 'textbook pass', \
     'front_vr.dat' using 1:2 with lines lw 2 lc rgb '#cc3311' title 'front'
unset arrow
unset label
set yrange [*:*]
set ylabel 'PSNR against the depth-only limit (dB)'
set title 'against what one depth layer allows'
plot 'bench.dat' using ($4==0 ? $1 : 1/0):3 with points pt 7 ps 0.8 lc rgb '#4477aa' title 'kernel', \
     'bench.dat' using ($4==1 ? $1 : 1/0):3 with points pt 7 ps 0.8 lc rgb '#ee7733' title 'visibility', \
     'bench.dat' using ($4==3 ? $1 : 1/0):3 with points pt 4 ps 1.5 lc rgb '#777777' title 'presets 1.0', \
     'bench.dat' using ($4==2 ? $1 : 1/0):3 with points pt 9 ps 2 lc rgb '#aa3377' title 'presets', \
     'bench.dat' using ($4==4 ? $1 : 1/0):3 with points pt 5 ps 2 lc rgb '#000000' title 'textbook pass', \
     'front_limit.dat' using 1:2 with lines lw 2 lc rgb '#cc3311' title 'front'
unset multiplot
