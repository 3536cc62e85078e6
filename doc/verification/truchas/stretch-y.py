"""Check of inputs/truchas/stretch-y.xml, the companion of stretch-ny.xml in Truchas'
test-stretch-y.py (compared there). Its own figures: truchas_fields.stretch_end_figures.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-y"
CHANGES = []


def figures(results, deck):
    return tf.stretch_end_figures(results, "y")
