#!/bin/bash
# The accuracy-against-cost table of the friction laws (BENCHMARKS.md, "The friction laws: accuracy against cost"):
# the reference case at three friction levels and three speeds (below, near, above v_cr = 205.6 m/s), four laws
# (J = 1, 2, 4 trapezoid; J = 2 Simpson) at four resolutions (elements and load advance halved together), against a
# one-section-a-node run at 1600 elements / 0.0125 m (20 kN/m: 3200 / 0.00625 m, and J = 1 and 4 also at 1600). CPU time (user) beside each JSON.
#   cargo build --release && bash benches/scripts/friction_laws.sh OUT && python3 benches/scripts/friction_laws.py OUT
# Finished runs are kept: run it again to fill in what an interruption left.
B="$(cd "$(dirname "$0")/../.." && pwd)/target/release/frictrack"
OUT=${1:-friction-laws}
mkdir -p "$OUT"
cd "$OUT"
law_file() { # name J quadrature
  printf '[friction.distributed]\nforce_per_length = %s\nsubdivisions = %s\nquadrature = "%s"\n' "$4" "$2" "$3" > "$1.toml"
}
for f in 5000 1000 20000; do
  for v in 150 200 260; do
    law_file truth-$f 1 trapezoid $f
    # Heavy friction converges slower: its reference is one halving finer, and J = 1 and 4 run one halving further.
    truth="1600 0.0125"; finest=""
    [ $f = 20000 ] && truth="3200 0.00625" && finest="1600 0.0125"
    out=truth.$f.$v.json
    set -- $truth
    [ -s $out ] || /usr/bin/time -f "%U" -o $out.time nice $B run truth-$f.toml --speed $v --elements $1 --load-advance $2 --format json > $out 2>/dev/null
    for law in "j1 1 trapezoid" "j2 2 trapezoid" "j4 4 trapezoid" "s2 2 simpson"; do
      set -- $law
      law_file $1-$f $2 $3 $f
      more=""; case $1 in j1|j4) [ -n "$finest" ] && more="$finest";; esac
      for lev in "100 0.2" "200 0.1" "400 0.05" "800 0.025" ${more:+"$more"}; do
        set -- $law; name=$1; set -- $lev
        out=$name.$f.$v.$1.json
        [ -s $out ] || /usr/bin/time -f "%U" -o $out.time nice $B run $name-$f.toml --speed $v --elements $1 --load-advance $2 --format json > $out 2>/dev/null
      done
    done
  done
done
