"""Check of inputs/truchas/stretch-x.xml, the companion of stretch-nx.xml in Truchas'
test-stretch-x.py (compared there). Its own figures: truchas_fields.stretch_end_figures.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-x"
CHANGES = []


def figures(results, deck):
    return tf.stretch_end_figures(results, "x")
