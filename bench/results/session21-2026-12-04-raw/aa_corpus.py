#!/usr/bin/python3
# Ad-hoc: corpus scenes at 320x240 with +A0.3, both renderers, SSIM as
# conformance.py computes it.
import sys, os, random
sys.path.insert(0, '/work/wt-lead/bench')
import conformance as C
zr = sys.argv[1]; out = sys.argv[2]; n = int(sys.argv[3])
root = '/work/shared/corpus/scenes'
rows = [l.rstrip('\n').split('\t') for l in open('/work/conf/base/corpus.tsv') if not l.startswith('#')]
rows = [r for r in rows if len(r) > 4 and r[1] == '0' and r[4] not in ('-', '') and float(r[4]) < 2.0]
random.seed(21)
pick = sorted(random.sample(rows, min(n, len(rows))))
os.makedirs(out, exist_ok=True)
for r in pick:
    rel = r[0]
    path = os.path.join(root, rel); cwd = os.path.dirname(path)
    name = rel.replace('/', '_').replace('.pov', '') + '.png'
    po = os.path.join(out, 'p_' + name); zo = os.path.join(out, 'z_' + name)
    size = ['+W320', '+H240', '+A0.3']
    if not os.path.exists(po):
        C.run(['nice', 'povray', '+I' + os.path.basename(path), '+O' + po] + size + ['-D', '+WT1', '-GA', '+L' + C.INCLUDE], cwd, 120)
    C.run(['nice', zr, '+I' + os.path.basename(path), '+O' + zo] + size + ['-D', '+WT1', '+L' + C.INCLUDE], cwd, 120)
    try:
        v = C.ssim(zo, po)
    except Exception as e:
        v = -1
    print(f'{rel}\t{r[3]}\t{v:.4f}', flush=True)
