"""landsim: ray-traced landscape renderer for scene simulation (docs/PYTHON.md).

    import landsim
    scenario = landsim.Scenario.load("scene.toml").set("sun.elevation", 30)
    image = landsim.render(scenario, spp=16)
    image.rgb, image.depth, image.object, image.manifest
"""
from ._landsim import (Image, Scenario, ScenarioError, __version__, info, read_image,
                       read_image_set, render, render_set, set_log_level, set_strict, tree)

__all__ = ["Image", "Scenario", "ScenarioError", "__version__", "info", "read_image",
           "read_image_set", "render", "render_set", "set_log_level", "set_strict", "tree"]
