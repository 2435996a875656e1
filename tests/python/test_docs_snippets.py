"""The docs' snippets and statements about the files run as written: OUTPUTS.md's OpenImageIO
reader of an EXR's ids, SENSOR.md's NDVI reader, the Python snippets of README.md, USING.md and
PYTHON.md (their renders made small; PYTHON.md's batch in test_docs_batch.py), CAMERAS.md's frame of the EXR's worldToCamera."""
import json
import os
import re

import numpy as np

from conftest import SOURCE_DIR, fenced, read_exr, run_cli, run_in, source_path


def snippet(doc, starts):
    """The indented code block of `doc` whose first line starts with `starts`."""
    text = open(os.path.join(SOURCE_DIR, "docs", doc)).read()
    for block in re.findall(r"(?:\n    [^\n]*)+", text):
        lines = [line[4:] for line in block.strip("\n").split("\n")]
        if lines[0].startswith(starts):
            return "\n".join(lines)
    raise AssertionError(f"no snippet starting {starts!r} in {doc}")


def test_sensor_ndvi_snippet_reads_the_reflectance_layers(tmp_path):
    run_cli("render", source_path("scenes/examples/ndvi.toml"), "--view", "overview", "--width",
            "64", "--spp", "2", "--out", str(tmp_path / "out"))
    names = {}
    run_in(tmp_path, fenced("docs/SENSOR.md", "import OpenImageIO as oiio, numpy"), names)
    ndvi = names["ndvi"]
    layers = read_exr(tmp_path / "out" / "overview.exr")
    assert ndvi.shape == layers["R"].shape
    assert np.all(np.abs(ndvi) <= 1.0)
    leaf = layers["object"] == 3  # the legend's leaf (checked below)
    assert leaf.sum() > 20, "too few leaf pixels to judge"
    assert np.median(ndvi[leaf]) > 0.6, np.median(ndvi[leaf])


def test_python_snippets_run_as_written(tmp_path, small_renders):
    # README.md and USING.md: one image of the default scene; USING.md also writes a set.
    names = {}
    run_in(tmp_path, fenced("README.md", "import landsim"), names)
    assert names["image"].rgb.shape == (18, 32, 3)
    names = {}
    run_in(tmp_path, fenced("docs/USING.md", "import landsim"), names)
    manifest = json.load(open(tmp_path / "out30" / "manifest.json"))
    assert len(manifest["images"]) == len(names["s"].views)
    # PYTHON.md's tour of the API, from the source folder (it loads an example by its path).
    names = {}
    run_in(SOURCE_DIR, fenced("docs/PYTHON.md", "import landsim"), names)
    image = names["image"]
    assert image.rgb.shape[1] == 32 and image.rgb.shape[2] == 3
    assert image.manifest["camera"]["width"] == 32
    assert names["s"].views[0] != "" and "highlands" in names["s"].views


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


def test_world_to_camera_takes_scene_frame_points(tmp_path):
    """CAMERAS.md: the EXR's worldToCamera takes terrain points less landsim/scene_origin; the
    camera model's position then maps to the camera frame's origin, its target onto the axis."""
    import json
    import OpenImageIO as oiio
    run_cli("render", "--spp", "1", "--width", "32", "--out", str(tmp_path / "out"))
    exr = [f for f in os.listdir(tmp_path / "out") if f.endswith(".exr")][0]
    spec = oiio.ImageInput.open(str(tmp_path / "out" / exr)).spec()
    m = np.array(spec.getattribute("worldToCamera"), dtype=float).reshape(4, 4)  # row vectors
    origin = np.array([float(v) for v in spec.getattribute("landsim/scene_origin").split()])
    camera = json.loads(spec.getattribute("landsim/camera"))

    def to_camera(terrain_point):
        return np.append(np.array(terrain_point) - origin, 1.0) @ m

    assert np.allclose(to_camera(camera["position"])[:3], 0.0, atol=1e-2)
    target = to_camera(camera["target"])[:3]
    assert abs(target[0]) < 1e-2 * abs(target[2]) and abs(target[1]) < 1e-2 * abs(target[2])
    # In terrain coordinates, without the origin subtracted, the camera is far from the origin.
    assert np.linalg.norm((np.append(camera["position"], 1.0) @ m)[:3]) > 1.0


def undefined_names(code):
    """The names a block reads at its top level or in its functions that it neither assigns,
    imports nor finds among the builtins: what a fresh interpreter would raise NameError on."""
    import ast
    import builtins
    tree = ast.parse(code)
    bound = set(dir(builtins))
    for node in ast.walk(tree):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            bound.update((a.asname or a.name).split(".")[0] for a in node.names)
        elif isinstance(node, ast.Name) and isinstance(node.ctx, (ast.Store, ast.Del)):
            bound.add(node.id)
        elif isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            bound.add(node.name)
        elif isinstance(node, ast.arg):
            bound.add(node.arg)
        elif isinstance(node, ast.ExceptHandler) and node.name:
            bound.add(node.name)
    read = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}
    return sorted(read - bound)


def test_every_python_block_stands_alone():
    """Each ```python block of the docs runs when pasted alone into a fresh interpreter: it
    imports what it uses (PYTHON.md's batch once used landsim and numpy without)."""
    import glob
    files = [source_path("README.md")] + sorted(glob.glob(source_path("docs", "*.md")))
    files += sorted(glob.glob(source_path("python", "*.md")))
    blocks = 0
    for path in files:
        for block in re.findall(r"```python\n(.*?)```", open(path).read(), re.S):
            blocks += 1
            missing = undefined_names(block)
            assert not missing, f"{path}: a python block uses {missing} without defining them"
    assert blocks >= 5
    assert undefined_names("x = np.zeros(3)\n") == ["np"]  # the check itself can fail
