#!/bin/bash
# What an accuracy costs (BENCHMARKS.md, "How close a run is, and what an accuracy costs"): `run --accuracy TOL` on the
# reference case, linear and with 5 kN/m of ballast friction, at 1 % and 0.1 %, each with its CPU time (user) and
# wall time; then the table, with the friction run's cost over the linear run's at the same tolerance.
#   cargo build --release && bash benches/scripts/accuracy_cost.sh OUT
# Finished runs are kept: run it again to fill in what an interruption left.
B="$(cd "$(dirname "$0")/../.." && pwd)/target/release/frictrack"
OUT=${1:-accuracy-cost}
mkdir -p "$OUT"
cd "$OUT"
for tol in 0.01 0.001; do
  for case in linear friction; do
    flags=""; [ $case = friction ] && flags="--distributed-friction 5000"
    out=$case.$tol.json
    [ -s $out ] || /usr/bin/time -f "%U %e" -o $out.time $B run $flags --accuracy $tol --format json > $out 2>/dev/null
  done
done
python3 - <<'PY'
import json
print('| case | TOL | status | resolutions | finest | CPU (user) | wall | CPU / linear |')
print('|---|---|---|---|---|---|---|---|')
for tol in ['0.01', '0.001']:
    linear = None
    for case in ['linear', 'friction']:
        j = json.load(open(f'{case}.{tol}.json'))
        a = j['accuracy']
        user, wall = map(float, open(f'{case}.{tol}.json.time').read().split())
        linear = user if case == 'linear' else linear
        r = a['resolutions'][-1]
        status = a['status']['kind'] + ('' if a['status']['kind'] == 'reached' else ': ' + ', '.join(a['status']['outcomes']))
        law = a.get('law')
        name = case + (f" (J = {law['subdivisions']})" if law else '')
        print(f"| {name} | {tol} | {status} | {len(a['resolutions'])} | {r['elements']} el, {r['load_advance']} m "
              f"| {user:.1f} s | {wall:.1f} s | {user / linear:.1f}× |")
PY
