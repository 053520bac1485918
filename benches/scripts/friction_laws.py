"""The table of benches/scripts/friction_laws.sh: per friction level and speed, each law's largest relative error
of the window's peaks and the friction work, and of the whole run's peaks, against the 1600-element run (3200 at 20 kN/m), at each
resolution, with its CPU time."""
import json, os, sys
DIR = sys.argv[1] if len(sys.argv) > 1 else 'friction-laws'
def outcomes(j):
    return {'down': j['max_downward_deflection']['value'], 'up': j['max_upward_deflection']['value'],
            'wdown': j['window_max_downward_deflection']['value'], 'wup': j['window_max_upward_deflection']['value'],
            'work': j['energy']['friction_dissipation']}
def t(path): return float(open(path + '.time').read().split()[-1])
laws = ['j1', 'j2', 'j4', 's2']
levels = [100, 200, 400, 800, 1600]
for f in [5000, 1000, 20000]:
    for v in [150, 200, 260]:
        tp = f'{DIR}/truth.{f}.{v}.json'
        if not os.path.exists(tp) or os.path.getsize(tp) == 0: continue
        truth = outcomes(json.load(open(tp)))
        reference = '3200 el, 0.00625 m' if f == 20000 else '1600 el, 0.0125 m'
        print(f'== f = {f} N/m, v = {v} m/s (truth: one section a node, {reference}, {t(tp):.1f} s)')
        for law in laws:
            row = []
            for e in levels:
                p = f'{DIR}/{law}.{f}.{v}.{e}.json'
                if not os.path.exists(p) or os.path.getsize(p) == 0:
                    if e < 1600: row.append('   —   ')
                    continue
                o = outcomes(json.load(open(p)))
                err = {k: abs(o[k] - truth[k]) / abs(truth[k]) for k in o}
                window = max(err['wdown'], err['wup'], err['work'])
                whole = max(err['down'], err['up'])
                row.append(f'{100*window:5.2f}/{100*whole:5.2f}% {t(p):6.2f}s')
            print(f'  {law}: ' + ' | '.join(row))
