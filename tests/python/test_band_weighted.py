"""scripts/band_weighted.py: a band's factor from monochromatic runs (docs/CANOPIES.md
"Measures"), checked on a run made up here, whose weighted mean is worked out by hand."""
import json
import subprocess
import sys

from conftest import source_path


def weighted(tmp_path, result, response, *extra):
    run = tmp_path / "brf.json"
    run.write_text(json.dumps(result))
    band = tmp_path / "band.csv"
    band.write_text("# a band\nwavelength_nm,response\n" + response)
    done = subprocess.run([sys.executable, source_path("scripts", "band_weighted.py"), str(run),
                           str(band), *extra], capture_output=True, text=True)
    return done


def test_trapezoids_of_response_times_factor(tmp_path):
    def factor(v):
        return {"brf": v, "brf_se": 0.01}
    result = {"level": "toa", "wavelengths_nm": [650.0, 660.0, 670.0],
              "directions": [{"zenith_deg": 0.0, "azimuth_deg": 0.0,
                              "bands": {"650nm": factor(0.3), "660nm": factor(0.2),
                                        "670nm": factor(0.1)}}]}
    # Response 1 at 650 rising to 3 at 670: trapezoid weights 5 x 1, 10 x 2, 5 x 3 = 5, 20, 15.
    done = weighted(tmp_path, result, "640,0\n650,1\n670,3\n680,0\n")
    assert done.returncode == 0, done.stderr
    row = done.stdout.splitlines()[1].split(",")
    want = (5 * 0.3 + 20 * 0.2 + 15 * 0.1) / 40
    assert abs(float(row[3]) - want) < 1e-6, done.stdout
    assert abs(float(row[4]) - 0.01) < 1e-6


def test_refuses_a_run_that_is_not_monochromatic(tmp_path):
    done = weighted(tmp_path, {"level": "toa", "directions": []}, "650,1\n")
    assert done.returncode != 0
    assert "not a monochromatic run" in done.stderr
