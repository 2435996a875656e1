"""landsim.info and landsim.tree against the program's own answers."""
import os

import numpy as np

import landsim
from conftest import cli_json, run_cli, source_path


def without_program(info):
    """The estimate less this process's own size (python3 is larger than landsim)."""
    info = dict(info)
    parts = dict(info.pop("memory_parts_bytes"))
    program = parts.pop("program")
    info["scene_bytes"] = info.pop("memory_estimate_bytes") - program
    info["parts"] = parts
    return info


def test_info_equals_the_programs():
    example = source_path("scenes", "examples", "camera_1km.toml")
    mine = landsim.info(landsim.Scenario.load(example))
    assert mine["memory_parts_bytes"]["program"] > 0
    assert without_program(mine) == without_program(cli_json("info", example))


def test_info_sees_keys_set_in_python():
    s = landsim.Scenario.default()
    dense = landsim.Scenario.default().set("species.0.density_per_ha", 400)
    assert landsim.info(dense)["instances"] != landsim.info(s)["instances"]
    assert without_program(landsim.info(dense)) == without_program(
        cli_json("info", "--set", "species.0.density_per_ha=400"))


def read_obj_counts(path):
    vertices = faces = 0
    with open(path) as f:
        for line in f:
            vertices += line.startswith("v ")
            faces += line.startswith("f ")
    return vertices, faces


def test_tree_is_the_mesh_the_program_writes(tmp_path):
    species = source_path("data", "species", "quaking_aspen.toml")
    t = landsim.tree(species, seed=3)
    obj = tmp_path / "aspen.obj"
    run_cli("tree", species, "--seed", "3", "--obj", str(obj))
    assert (len(t["vertices"]), len(t["faces"])) == read_obj_counts(obj)
    assert t["vertices"].shape[1] == 3 and t["vertices"].dtype == np.float32
    assert t["faces"].dtype == np.uint32 and t["faces"].max() < len(t["vertices"])
    info = cli_json("tree", species, "--seed", "3")
    assert len(t["faces"]) == info["triangles"]
    assert t["stats"]["leaves"] == info["leaves"]


def test_tree_parts_name_trunk_and_leaves_and_seeds_differ():
    species = source_path("data", "species", "quaking_aspen.toml")
    t = landsim.tree(species, seed=1)
    names = t["part_names"]
    assert names[0] == "trunk" and names[-1] == "leaves"
    assert (t["parts"] == 0).any() and (t["parts"] == 4).any()
    # Trunk faces are low, leaves high: the parts are the faces they say.
    z = t["vertices"][:, 2]
    trunk_z = z[t["faces"][t["parts"] == 0]].mean()
    leaf_z = z[t["faces"][t["parts"] == 4]].mean()
    assert leaf_z > trunk_z
    other = landsim.tree(species, seed=2)
    assert len(other["faces"]) != len(t["faces"]) or not np.array_equal(
        other["vertices"], t["vertices"])


def test_tree_age_grows_it():
    species = source_path("data", "species", "quaking_aspen.toml")
    young = landsim.tree(species, seed=1, age=5)
    old = landsim.tree(species, seed=1, age=40)
    assert young["stats"]["height_m"] < old["stats"]["height_m"]
