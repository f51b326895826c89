#!/usr/bin/python3
# Ad-hoc: stock scenes at 320x240 with antialiasing +A0.3 (both
# renderers' default method 1), SSIM as conformance.py computes it.
import sys, os, random
sys.path.insert(0, '/work/wt-lead/bench')
import conformance as C
zr = sys.argv[1]; out = sys.argv[2]; n = int(sys.argv[3])
extra = sys.argv[4:]
rows = [l.split('\t') for l in open('/work/conf/base/stock.tsv') if not l.startswith('#')]
rows = [r for r in rows if len(r) > 4 and r[1] == '0' and float(r[4]) < 1.0]
random.seed(21)
pick = sorted(random.sample(rows, min(n, len(rows))))
os.makedirs(out, exist_ok=True)
for r in pick:
    rel = r[0]
    path = os.path.join(C.EXAMPLES, rel); cwd = os.path.dirname(path)
    po = os.path.join(out, 'p_' + C.flat(rel)); zo = os.path.join(out, 'z_' + C.flat(rel))
    size = ['+W320', '+H240', '+A0.3'] + extra
    if not os.path.exists(po):
        C.run(['nice', 'povray', '+I' + path, '+O' + po] + size + ['-D', '+WT1', '-GA', '+L' + C.INCLUDE, '+L' + cwd], cwd, 120)
    rc, s, err = C.run(['nice', zr, '+I' + path, '+O' + zo] + size + ['-D', '+WT1', '+L' + C.INCLUDE, '+L' + cwd], cwd, 120)
    try:
        v = C.ssim(zo, po)
    except Exception as e:
        v = -1
    print(f'{rel}\t{r[3]}\t{v:.4f}', flush=True)
