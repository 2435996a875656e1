"""Shared helpers of the Python module's tests (run by ctest with PYTHONPATH at the build's
package and LANDSIM_CLI, LANDSIM_SOURCE_DIR set)."""
import contextlib
import io
import json
import os
import re
import subprocess

import numpy as np
import pytest

SOURCE_DIR = os.environ["LANDSIM_SOURCE_DIR"]
CLI = os.environ["LANDSIM_CLI"]


def source_path(*parts):
    return os.path.join(SOURCE_DIR, *parts)


def run_cli(*args, cwd=None):
    """Runs the landsim program; returns its stdout (fails the test on a non-zero exit)."""
    done = subprocess.run([CLI, *args], cwd=cwd, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def cli_json(*args):
    return json.loads(run_cli(*args, "--json"))


def read_exr(path):
    """Every channel of an EXR by name, in its stored type, read by OpenImageIO (not by
    landsim's own reader)."""
    import OpenImageIO as oiio
    image = oiio.ImageInput.open(str(path))
    assert image is not None, oiio.geterror()
    spec = image.spec()
    channels = {}
    for c, name in enumerate(spec.channelnames):
        stored = str(spec.channelformat(c))
        fmt = oiio.UINT if stored.startswith("uint") else oiio.FLOAT
        channels[name] = image.read_image(0, 0, c, c + 1, fmt)[:, :, 0]
    image.close()
    return channels


@pytest.fixture
def small_default():
    """The embedded scenario, small and quick."""
    import landsim
    return landsim.Scenario.default().set("render.spp", 2).set("views.0.width", 96).set(
        "views.0.height", 54)


def fenced(path, starts):
    """The ```python block of the file at `path` (from the source folder) whose first line starts
    with `starts`."""
    text = open(os.path.join(SOURCE_DIR, path)).read()
    for block in re.findall(r"```python\n(.*?)```", text, re.S):
        if block.startswith(starts):
            return block
    raise AssertionError(f"no python block starting {starts!r} in {path}")


def run_in(folder, code, names):
    """Runs `code` with `folder` as the working folder; returns what it printed."""
    cwd = os.getcwd()
    os.chdir(folder)
    out = io.StringIO()
    try:
        with contextlib.redirect_stdout(out):
            exec(code, names)
    finally:
        os.chdir(cwd)
    return out.getvalue()


@pytest.fixture
def small_renders(monkeypatch):
    """landsim.render and render_set at 1 sample and 32 pixels across, whatever a snippet asks:
    the snippets run as written, only smaller."""
    import landsim
    render, render_set = landsim.render, landsim.render_set

    def small(kwargs):
        kwargs.update(spp=1, width=32)
        kwargs.pop("height", None)
        return kwargs

    monkeypatch.setattr(landsim, "render", lambda s, **kw: render(s, **small(kw)))
    monkeypatch.setattr(landsim, "render_set", lambda s, out, **kw: render_set(s, out, **small(kw)))
    return landsim
