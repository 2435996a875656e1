"""landsim.render and landsim.render_set: the program's images, in memory and on disk."""
import json
import threading
import time
import _thread

import numpy as np
import pytest

import landsim
from conftest import read_exr, run_cli, source_path


def render_with_cli(out, *args):
    run_cli("render", "--out", str(out), "--spp", "2", "--width", "96", "--height", "54",
            "--set", "sun.elevation=30", *args)


def test_render_arrays_equal_the_exr_the_program_writes(tmp_path, small_default):
    image = landsim.render(small_default.set("sun.elevation", 30))
    render_with_cli(tmp_path, "--view", "crater")
    exr = read_exr(tmp_path / "crater.exr")
    assert set(exr) == set(image.layers)
    for name, channel in exr.items():
        mine = image.layers[name]
        assert mine.dtype == channel.dtype, name
        assert np.array_equal(mine, channel, equal_nan=True), name
    # The shaped views are the same planes.
    assert np.array_equal(image.rgb[:, :, 1], exr["G"])
    assert np.array_equal(image.depth, exr["Z"])
    assert np.array_equal(image.object, exr["object"])
    manifest = json.loads((tmp_path / "manifest.json").read_text())["images"][0]
    mine = image.manifest
    for key in ("view", "camera", "irradiance"):
        assert mine[key] == manifest[key], key
    assert image.metadata["scenario_hash"] == small_default.hash


def test_render_is_the_same_on_one_thread_and_two(small_default):
    one = landsim.render(small_default, threads=1)
    two = landsim.render(small_default, threads=2)
    assert np.array_equal(one.rgb, two.rgb)
    assert np.array_equal(one.layers["instance"], two.layers["instance"])


def test_render_arguments_win_over_the_scenario(small_default):
    image = landsim.render(small_default, width=48, spp=1)
    assert (image.width, image.height) == (48, 27)
    assert image.spp == 1
    with pytest.raises(landsim.ScenarioError) as e:
        landsim.render(small_default, view="nowhere")
    assert "crater" in str(e.value)


def test_render_set_writes_what_the_program_writes(tmp_path, small_default):
    mine, theirs = tmp_path / "python", tmp_path / "cli"
    done = landsim.render_set(small_default.set("sun.elevation", 30), mine)
    render_with_cli(theirs)
    assert [i["view"] for i in done["images"]] == ["crater"]
    for name in ("crater.exr", "crater.png", "manifest.json"):
        assert (mine / name).exists(), name
    a, b = read_exr(mine / "crater.exr"), read_exr(theirs / "crater.exr")
    for name in b:
        assert np.array_equal(a[name], b[name], equal_nan=True), name


def test_the_gil_is_released_while_rendering(small_default):
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    landsim.render(small_default.set("render.spp", 16), width=192)
    stop.set()
    counter.join()
    assert len(ticks) > 20


def test_progress_is_reported_on_the_calling_thread(small_default):
    seen = []
    caller = threading.get_ident()
    landsim.render(small_default.set("render.spp", 8), width=192,
                   progress=lambda image, f: seen.append((image, f, threading.get_ident())))
    assert seen, "no progress reported"
    assert all(image == "crater" and 0 < f <= 1 and t == caller for image, f, t in seen)
    assert seen[-1][1] == 1.0


def test_an_exception_in_progress_stops_the_render(small_default):
    class Enough(Exception):
        pass

    reports = []

    def stop(image, fraction):
        reports.append(fraction)
        raise Enough()

    with pytest.raises(Enough):
        landsim.render(small_default.set("render.spp", 1536), width=320, progress=stop)
    # The whole render would take minutes (320 x 180 x 1536 samples: 160 s on the 2-core VM);
    # the first report comes after 5% of the tiles, and a render that went on would report
    # again (and raise again): one early report is the render stopped there, whatever the
    # machine's speed.
    assert len(reports) == 1
    assert reports[0] < 0.5


def test_ctrl_c_cancels_a_set_cleanly_and_resume_finishes_it(tmp_path, small_default):
    slow = small_default.copy().set("render.spp", 4096).set("views.0.width", 320).set(
        "views.0.height", 180)
    timer = threading.Timer(1.0, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        landsim.render_set(slow, tmp_path)
    timer.cancel()
    # The whole render would take minutes; a render that ignored the interrupt and finished
    # would have written its manifest before Python raised it.
    assert not (tmp_path / "manifest.json").exists()
    assert not (tmp_path / "crater.exr").exists()
    # The same set, quick, renders into the folder afterwards.
    done = landsim.render_set(small_default, tmp_path)
    assert len(done["images"]) == 1 and (tmp_path / "manifest.json").exists()


def test_a_stored_set_reads_back_as_the_images_render_returns(tmp_path, small_default):
    landsim.render_set(small_default, tmp_path)
    images = landsim.read_image_set(tmp_path)
    assert [i.view for i in images] == ["crater"]
    stored, fresh = images[0], landsim.render(small_default)
    assert set(stored.layers) == set(fresh.layers)
    for name, array in fresh.layers.items():
        assert np.array_equal(stored.layers[name], array, equal_nan=True), name
    assert stored.manifest["view"] == "crater" and "irradiance" in stored.manifest
    assert stored.metadata["scenario_hash"] == small_default.hash
    assert stored.spp == fresh.spp == 2


def test_an_image_saves_and_reads_back_with_its_bands(tmp_path):
    ndvi = landsim.Scenario.load(source_path("scenes", "examples", "ndvi.toml"))
    image = landsim.render(ndvi, spp=1, width=64)
    assert any(name.startswith("band.") for name in image.layers)
    image.save(tmp_path / "again.exr")
    back = landsim.read_image(tmp_path / "again.exr")
    assert set(back.layers) == set(image.layers)
    for name, array in image.layers.items():
        assert np.array_equal(back.layers[name], array, equal_nan=True), name


def test_a_file_that_is_not_a_landsim_image_is_refused_by_name(tmp_path):
    bad = tmp_path / "notes.exr"
    bad.write_text("not an image")
    with pytest.raises(landsim.ScenarioError) as e:
        landsim.read_image(bad)
    assert "notes.exr" in str(e.value)
    with pytest.raises(landsim.ScenarioError) as e:
        landsim.read_image_set(tmp_path)
    assert "manifest.json" in str(e.value)


def test_illumination_truth_marks_shade_and_sky(small_default):
    # docs/OUTPUTS.md "Illumination truth": the default scene's low sun leaves shade behind its
    # trees and slopes; the sky's pixels hold no surface.
    image = landsim.render(small_default.copy().set("render.illumination_layers", True))
    sunlit = image.layers["illumination.sunlit"]
    sky_view = image.layers["illumination.sky_view"]
    surface = image.layers["illumination.surface"]
    seen = surface > 0
    assert seen.any() and (~seen).any()
    assert np.isnan(sunlit[~seen]).all() and np.isnan(sky_view[~seen]).all()
    assert ((sunlit[seen] >= 0) & (sunlit[seen] <= 1)).all()
    assert ((sky_view[seen] >= 0) & (sky_view[seen] <= 1)).all()
    assert (sunlit[seen] == 0).any() and (sunlit[seen] == 1).any()
    assert (sky_view[seen] < 0.9).any()
