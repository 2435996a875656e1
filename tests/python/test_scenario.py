"""landsim.Scenario: load, set, from_dict, to_toml and their refusals."""
import copy
import tomllib

import pytest

import landsim
from conftest import source_path


def test_load_reads_the_file_and_its_views():
    s = landsim.Scenario.load(source_path("scenes", "examples", "camera_1km.toml"))
    assert s.source.endswith("camera_1km.toml")
    assert len(s.views) >= 1
    assert s.sets == []


def test_set_changes_the_key_and_the_hash():
    s = landsim.Scenario.default()
    before = s.hash
    s.set("sun.elevation", 30)
    assert s.hash != before
    assert s.to_dict()["sun"]["elevation"] == 30
    assert s.sets == ["sun.elevation=30"]


def test_set_indexes_arrays_of_tables_and_takes_strings_lists_and_bools():
    s = landsim.Scenario.default()
    s.set("views.0.fov", 25.5).set("render.season", "winter")
    s.set("atmosphere.aerosol.colour", [0.9, 0.9, 1.0])
    d = s.to_dict()
    assert d["views"][0]["fov"] == 25.5
    assert d["render"]["season"] == "winter"
    assert d["atmosphere"]["aerosol"]["colour"] == [0.9, 0.9, 1.0]


def test_a_value_out_of_range_is_refused_with_key_and_reason_and_nothing_changes():
    s = landsim.Scenario.default()
    before = s.hash
    with pytest.raises(landsim.ScenarioError) as e:
        s.set("sun.elevation", 120)
    assert isinstance(e.value, ValueError)
    assert e.value.key == "sun.elevation"
    assert "0" in e.value.reason and "90" in e.value.reason and "120" in e.value.reason
    assert "sun.elevation=120" in str(e.value)
    assert s.hash == before and s.sets == []


def test_an_unknown_key_is_refused_with_a_suggestion():
    with pytest.raises(landsim.ScenarioError) as e:
        landsim.Scenario.default().set("sun.elevashun", 12)
    assert "did you mean 'elevation'" in str(e.value)


def test_a_value_toml_cannot_hold_is_a_type_error():
    with pytest.raises(TypeError) as e:
        landsim.Scenario.default().set("sun.elevation", None)
    assert "sun.elevation" in str(e.value)


def test_a_missing_file_names_it():
    with pytest.raises(landsim.ScenarioError) as e:
        landsim.Scenario.load("/nonexistent/scene.toml")
    assert "/nonexistent/scene.toml" in str(e.value)


def test_a_bad_file_gives_file_and_line():
    text = "[terrain]\nelevation = 'x.asc'\n[sun]\nelevation = 'high'\n[[views]]\nname = 'a'\n"
    with pytest.raises(landsim.ScenarioError) as e:
        landsim.Scenario.from_toml(text, base_dir=source_path("data", "terrain"))
    assert "<toml>:" in str(e.value)


def test_to_dict_and_from_dict_round_trip():
    s = landsim.Scenario.default().set("sun.azimuth", 200)
    again = landsim.Scenario.from_dict(s.to_dict(), base_dir=s.base_dir)
    assert again.to_dict() == s.to_dict()
    # The same scenario, the same hash (the images' scenario_hash; resume keeps them).
    assert again.hash == s.hash
    assert again.views == s.views


def test_from_dict_validates_like_a_file():
    d = landsim.Scenario.default().to_dict()
    d["render"]["spp"] = 0
    with pytest.raises(landsim.ScenarioError) as e:
        landsim.Scenario.from_dict(d, base_dir=landsim.Scenario.default().base_dir)
    assert e.value.key == "render.spp"


def test_to_toml_is_toml_with_the_keys_set():
    s = landsim.Scenario.default().set("sun.elevation", 42.5)
    parsed = tomllib.loads(s.to_toml())
    assert parsed["sun"]["elevation"] == 42.5
    assert "terrain" in parsed and "views" in parsed


def test_copies_are_independent():
    base = landsim.Scenario.default()
    a = base.copy().set("sun.elevation", 10)
    b = copy.deepcopy(base).set("sun.elevation", 20)
    assert a.to_dict()["sun"]["elevation"] == 10
    assert b.to_dict()["sun"]["elevation"] == 20
    assert base.sets == []
