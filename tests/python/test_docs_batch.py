"""PYTHON.md's batch of twenty renders runs as written (smaller): in a file of its own, so that
ctest runs it beside the other snippets."""
import json

import numpy as np

from conftest import fenced, run_in


def test_python_batch_snippet_measures_the_canopy(tmp_path, small_renders):
    """PYTHON.md's batch: twenty renders, each line a finite canopy luminance; the classes it
    takes for bark and leaf are the legend's."""
    code = fenced("docs/PYTHON.md", "import landsim\nimport numpy as np\n\nbase = ")
    # As a user pastes it: a namespace of its own, nothing carried over (its `import landsim`
    # finds the module whose renders small_renders made small).
    names = {}
    printed = run_in(tmp_path, code, names).strip().split("\n")
    assert len(printed) == 20, printed
    luminance = [float(line.split()[-1]) for line in printed]
    assert all(np.isfinite(v) and v > 0.0 for v in luminance), printed
    legend = json.loads(names["image"].metadata["legend"])["object"]["values"]
    assert legend["2"] == "bark" and legend["3"] == "leaf", legend
