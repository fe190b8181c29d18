#!/bin/sh
# Wall time of povwall against POV-Ray 3.7 on one scene: alternating runs, median of N.
# usage: bench/compare_povray.sh POVWALL_BINARY SCENE.pov [SIZE] [RUNS] [THREADS]
# Prints each run, the medians, the ratio, and povwall's image diff against POV-Ray's.
set -eu
bin=$1 scene=$2 size=${3:-600} runs=${4:-3} threads=${5:-2}
out=$(mktemp -d)
now() { date +%s.%N; }
i=1
while [ "$i" -le "$runs" ]; do
    t0=$(now)
    povray +I"$scene" +O"$out/povray.png" +W"$size" +H"$size" -A +WT"$threads" -D -V \
        +L/usr/share/povray-3.7/include >/dev/null 2>&1
    t1=$(now)
    "$bin" render "$scene" -o "$out/povwall.png" -W "$size" -H "$size" \
        --threads "$threads" >/dev/null 2>&1
    t2=$(now)
    echo "run $i: povray $(echo "$t1 - $t0" | bc) s, povwall $(echo "$t2 - $t1" | bc) s" |
        tee -a "$out/runs"
    i=$((i + 1))
done
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
p=$(awk '{print $4}' "$out/runs" | median)
w=$(awk '{print $7}' "$out/runs" | median)
echo "median: povray $p s, povwall $w s, speed-up $(echo "scale=2; $p / $w" | bc)x"
"$bin" diff "$out/povwall.png" "$out/povray.png" || true
rm -rf "$out"
