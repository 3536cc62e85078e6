"""same_exodus.py A.exo B.exo: the same steps (times) and the same nodal, element and global
variables (but the wall time) to 1e-9, else exit 1 naming what differs (disk_full.sh; needs
scipy: python3-scipy in packages/install.sh)."""
import sys
import numpy as np
from scipy.io import netcdf_file
a = netcdf_file(sys.argv[1], 'r', mmap=False)
b = netcdf_file(sys.argv[2], 'r', mmap=False)
bad = 0
keys = sorted(k for k in a.variables if k.startswith('vals') or k == 'time_whole')
names = [bytes(r).decode().strip('\0') for r in a.variables['name_glo_var'][:]]
for k in keys:
    x, y = a.variables[k][:], b.variables[k][:]
    if k == 'vals_glo_var':  # but the wall time
        keep = [i for i, n in enumerate(names) if n != 'wall_time']
        x, y = x[:, keep], y[:, keep]
    if x.shape != y.shape:
        print(k, 'shapes', x.shape, y.shape); bad += 1; continue
    finite = np.isfinite(x) | np.isfinite(y)
    if not np.array_equal(np.isfinite(x), np.isfinite(y)) or not np.allclose(x[finite], y[finite], rtol=1e-9, atol=1e-9):
        print(k, 'differs, max', np.nanmax(np.abs(x - y))); bad += 1
print(len(keys), 'variables compared,', bad, 'differ; steps', len(a.variables['time_whole'][:]))
sys.exit(1 if bad else 0)
