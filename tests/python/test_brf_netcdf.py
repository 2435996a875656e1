"""landsim brf's NetCDF output as an xarray user reads it: CF metadata decoded, the BRF along
the direction dimension with its coordinates, the budgets along illumination, every number
the same as brf.json's."""
import json

import numpy as np
import pytest
import xarray as xr

from conftest import run_cli, source_path


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    out = tmp_path_factory.mktemp("brf")
    run_cli("brf", source_path("scenes", "disort", "case_1b.toml"), "--spp", "64",
            "--budget-paths", "500", "--out", str(out))
    with open(out / "brf.json") as f:
        document = json.load(f)
    with xr.open_dataset(out / "brf.nc") as ds:
        yield ds.load(), document


def test_the_dataset_follows_cf_and_names_its_dimensions(measured):
    ds, _ = measured
    assert ds.attrs["Conventions"] == "CF-1.8"
    assert dict(ds.sizes) == {"direction": 76, "illumination": 2}
    assert ds["brf"].attrs["standard_name"] == "surface_bidirectional_reflectance"
    assert ds["brf"].attrs["ancillary_variables"] == "brf_standard_error"
    assert ds["sensor_zenith_angle"].attrs["units"] == "degree"
    # The principal plane's signed zenith is a coordinate of the BRF: select by it.
    assert "view_zenith_principal_plane" in ds["brf"].coords
    assert list(ds["illumination"].values) == ["sun", "isotropic"]


def test_every_number_is_brf_json_s(measured):
    ds, document = measured
    directions = document["directions"]
    np.testing.assert_array_equal(ds["brf"].values, [d["brf"] for d in directions])
    np.testing.assert_array_equal(ds["brf_standard_error"].values, [d["brf_se"] for d in directions])
    np.testing.assert_array_equal(ds["view_zenith_principal_plane"].values,
                                  [d["view_zenith_deg"] for d in directions])
    np.testing.assert_array_equal(ds["sensor_azimuth_angle"].values,
                                  [d["azimuth_deg"] for d in directions])
    # RAMI's frame beside the compass's: 0 on the sun's side of the plane, 180 opposite.
    np.testing.assert_array_equal(ds["rami_relative_azimuth_angle"].values,
                                  [d["relative_azimuth_deg"] for d in directions])
    assert sorted(set(ds["rami_relative_azimuth_angle"].values)) == [0.0, 180.0]
    assert "rami_relative_azimuth_angle" in ds["brf"].coords
    for share in ("albedo", "absorbed_soil", "absorbed_haze", "soil_direct", "total"):
        assert ds[share].sel(illumination="sun").item() == document["budget"][share]["mean"]
        assert ds[share].sel(illumination="isotropic").item() == \
            document["budget_isotropic"][share]["mean"]
        assert ds[share + "_standard_error"].sel(illumination="sun").item() == \
            document["budget"][share]["se"]
