"""Check of inputs/truchas/contact-2.xml: Truchas' sm-contact test2.py.

test2.py compares the displacement of Series 1 (t = 0) with the golden output to 1e-9 m (max
abs). The two free quarters (held only by frictionless contact) may move rigidly along the
cube's y and z and turn about its x wherever no pair holds them, so the problem has many
solutions; Kiln gives the minimum-norm one ("Free Motions" = "Minimum Norm", doc/contact.md),
Truchas whatever its iterative solver reached. The figures (truchas_contact.py):
- the displacement against the golden (test2.py's check);
- against the golden's own minimum-norm element (the golden with the free motions that the
  contact conditions allow taken out by the same quadratic programme): the golden's free
  quarters carry translations along the cube's z of 2.8e-9 and 1.8e-9 m, so it is not the
  minimum-norm solution, and these alone put it 2.6e-9 m (max abs component) from Kiln,
  beyond test2.py's 1e-9 m; in y and about x it is at the minimum (the quarters touch
  across gap 11, as in Kiln; its shift there is 1.3e-11 m). Kiln is 3.6e-10 m from that
  element (within 1e-9): the golden's quarters touch at x > 0 with up to 2.5e3 Pa of
  compression across gap 11, which nothing balances on a quarter held only by frictionless
  contact (the exact pressure there is 0, as in Kiln);
- Kiln's distance from its own minimum-norm element (0 to round-off: Kiln's answer is it);
- the contact conditions: no tension (pairs held shut by Minimum Norm carry round-off only),
  no penetration, p g = 0.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_contact as tc  # noqa: E402

TEST = "sm-contact/contact-2"
CHANGES = []
GOLDEN = "../shared/truchas-tests/sm-contact/contact-2_golden/contact-2.h5"
TOLERANCE = 1e-9  # test2.py: compare_max(displacement, golden, 1e-9)


def figures(results, deck):
    return tc.figures(results, deck, "test2.py", TOLERANCE, GOLDEN)
