"""complete_steps.py BASE.running.xmf: the results of a run killed mid-run (disk_full.sh
killed). The XDMF index must parse, and every dataset it names must be in its HDF5 file with
the index's dimensions (temperatures > 0 K: written); each step it lists has its time, dt and cycle, the
time the index gives. At most one step (the one being written when the run died) may be in
the HDF5 file beyond the index. Prints the number of complete steps; exit 1 on a failure.
Needs h5py (python3-h5py in packages/install.sh)."""
import os
import sys
import xml.etree.ElementTree as ET

import h5py

xmf = sys.argv[1]
grids = [g for g in ET.parse(xmf).iter('Grid') if g.find('Time') is not None]
files = {}
problems = []
for grid in grids:
    for item in grid.iter('DataItem'):
        name, dataset = item.text.strip().split(':', 1)
        path = os.path.join(os.path.dirname(xmf), name)
        f = files.setdefault(path, h5py.File(path, 'r'))
        if dataset not in f:
            problems.append('%s: %s is missing' % (grid.get('Name'), dataset))
            continue
        values = f[dataset][()]
        dims = tuple(int(d) for d in item.get('Dimensions').split())
        if values.shape != dims:
            problems.append('%s: %s has shape %s, the index says %s' %
                            (grid.get('Name'), dataset, values.shape, dims))
        elif dataset.endswith('/temperature') and not (values > 0).all():
            # A dataset created but never written reads as its fill value, 0.
            problems.append('%s: %s holds temperatures that are not > 0 K (not written?)' %
                            (grid.get('Name'), dataset))
        if dataset.startswith('/steps/'):
            step = f[dataset.rsplit('/', 1)[0]]
            time = float(grid.find('Time').get('Value'))
            if not all(a in step.attrs for a in ('time', 'dt', 'cycle')):
                problems.append('%s: lacks its time, dt or cycle' % step.name)
            elif abs(step.attrs['time'] - time) > 1e-12 * max(1.0, abs(time)):
                problems.append('%s: time %g, the index says %g' % (step.name, step.attrs['time'], time))
for path, f in files.items():
    extra = len(f['steps']) - len(grids)
    if not 0 <= extra <= 1:
        problems.append('%s holds %d steps, the index %d' % (path, len(f['steps']), len(grids)))
for p in problems:
    print('complete_steps.py:', p)
print('%d complete steps' % len(grids))
sys.exit(1 if problems or not grids else 0)
