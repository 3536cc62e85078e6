"""Check of inputs/truchas/viscoplastic-1d.xml: Truchas' sm-viscoplastic/viscoplastic-1d.inp,
test.py's quantities.

The bar is in a uniform state: strain (1e-3, 0, 0, 0, 0, 0), stress (4e6, 2e6, 2e6, 0, 0, 0)
Pa, von Mises stress 2e6 Pa, and the power law (A = 1e-12, n = 0.5) flows at
eps_dot_p = A sigma_vM^n = sqrt(2) 1e-9 1/s, which changes the stress by ~1e-6 relative, so
the equivalent plastic strain is t sqrt(2) 1e-9. test.py's tolerances, at every output: the
von Mises stress and the von Mises strain to 1e-5 relative (loose "so the tiny influence of
increasing plastic strain on the strain and stress fields is neglected"), the plastic strain
rate to 1e-12 absolute (Kiln: 1e-5 relative, the same influence on the rate), and the
plastic strain against t sqrt(2) 1e-9 (test.py compares Truchas' e_plastic, its own
measure, with a constant sqrt(4.5) 1e-9 to 1e-8 absolute, which any value below 1e-8 meets;
Kiln checks its equivalent plastic strain against t times the rate to 1e-5 relative of the
final value).
"""
import sys
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-viscoplastic/viscoplastic-1d"
# The deck is posed as Truchas' but for the mesh's rotation (Kiln's box has none; the state
# is uniform, so the rotation does not change it): no change to the deck here.
CHANGES = []
RATE = np.sqrt(2.0) * 1e-9  # [1/s]
STRESS = 2e6  # von Mises [Pa]
STRAIN = 1e-3  # von Mises of the strain, Truchas' formula [-]


def von_mises(t):
    """test.py's von_mises: rows in Kiln's order xx yy zz xy yz xz."""
    return np.sqrt(((t[:, 0] - t[:, 1]) ** 2 + (t[:, 1] - t[:, 2]) ** 2 + (t[:, 2] - t[:, 0]) ** 2
                    + 6 * (t[:, 3] ** 2 + t[:, 4] ** 2 + t[:, 5] ** 2)) / 2)


def figures(results, deck):
    steps = tf.kiln_steps(results)
    with h5py.File(results, "r") as h5:
        names = sorted(h5["steps"].keys())
        plastic = [h5["steps"][n]["plastic_strain"][...] for n in names]
        rate = [h5["steps"][n]["plastic_strain_rate"][...] for n in names]
    errors = {"stress": 0.0, "strain": 0.0, "rate": 0.0, "plastic": 0.0}
    for step, p, r in zip(steps, plastic, rate):
        errors["stress"] = max(errors["stress"],
                               float(np.abs(von_mises(step.stress) / STRESS - 1).max()))
        errors["strain"] = max(errors["strain"],
                               float(np.abs(von_mises(step.strain) / STRAIN - 1).max()))
        if step.time > 0:
            errors["rate"] = max(errors["rate"], float(np.abs(r / RATE - 1).max()))
        errors["plastic"] = max(errors["plastic"],
                                float(np.abs(p - step.time * RATE).max()) / (0.5 * RATE))
    final = steps[-1]
    return [
        tf.figure("max relative error of the von Mises stress (2e6 Pa) over cells and outputs",
                  errors["stress"], "test.py: 1e-5 relative", errors["stress"] <= 1e-5,
                  exact=0.0),
        tf.figure("max relative error of the von Mises strain (1e-3) over cells and outputs",
                  errors["strain"], "test.py: 1e-5 relative", errors["strain"] <= 1e-5,
                  exact=0.0),
        tf.figure("max relative error of the plastic strain rate (sqrt(2) 1e-9 1/s), t > 0",
                  errors["rate"], "test.py: 1e-12 absolute (7e-4 relative); Kiln 1e-5 relative",
                  errors["rate"] <= 1e-5, exact=0.0),
        tf.figure("max |plastic strain - t sqrt(2) 1e-9| / (0.5 s sqrt(2) 1e-9) over cells and "
                  "outputs", errors["plastic"], "1e-5 relative to the final value",
                  errors["plastic"] <= 1e-5 and final.time == 0.5, exact=0.0),
    ]
