"""The docs' snippets run as written: OUTPUTS.md's OpenImageIO reader of an EXR's ids."""
import os
import re

import numpy as np

from conftest import SOURCE_DIR, run_cli


def snippet(doc, starts):
    """The indented code block of `doc` whose first line starts with `starts`."""
    text = open(os.path.join(SOURCE_DIR, "docs", doc)).read()
    for block in re.findall(r"(?:\n    [^\n]*)+", text):
        lines = [line[4:] for line in block.strip("\n").split("\n")]
        if lines[0].startswith(starts):
            return "\n".join(lines)
    raise AssertionError(f"no snippet starting {starts!r} in {doc}")


def test_outputs_reading_snippet_reads_ids_exactly(tmp_path):
    run_cli("render", "--spp", "1", "--width", "48", "--out", str(tmp_path / "out"))
    code = snippet("OUTPUTS.md", "import json, OpenImageIO")
    # The snippet names out/v.exr; the default scene's image is the one EXR written.
    exr = [f for f in os.listdir(tmp_path / "out") if f.endswith(".exr")]
    assert len(exr) == 1, exr
    os.replace(tmp_path / "out" / exr[0], tmp_path / "out" / "v.exr")
    names = {}
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        exec(code, names)
    finally:
        os.chdir(cwd)
    species = names["species"]
    assert species.dtype == np.uint32
    ids = {int(v["id"]) for v in names["legend"]["species"]["values"]}
    seen = set(np.unique(species).tolist()) - {names["legend"]["species"]["none"]}
    assert seen, "no species in the default scene's image"
    assert seen <= ids, f"ids {sorted(seen - ids)[:5]} are not in the legend"
