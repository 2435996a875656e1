"""RAMI-III HET01 in Blender Cycles, the peer of `landsim brf` (bench/rami_vs_cycles.sh).

Run by Blender: blender -b --factory-startup -P bench/cycles_het01.py -- OUT_JSON TARGET [VIEWS]

Builds the scene from the same files landsim reads (data/rami/het01_UNI_sphere.def and
het01_UNI_instances.def): every leaf disc a 12-gon of the disc's area (its corners at
1.0233 radii: a 12-gon inscribed in the circle has 4.5% less area, which reads as a 0.8% lower
BRF at nadir), the 15 spheres of a 100 m cell, the cell
copied 7 x 7 around the centre with a Lambertian soil under all of it; bi-Lambertian leaves
(Diffuse + Translucent BSDFs, r 0.4957, t 0.4409), soil 0.159, a collimated sun of 1 W/m2 at
zenith 20 degrees from the east (+x), a black world. Each view of RAMI's principal plane is an
orthographic camera whose image covers exactly one period of the ground: the mean of its
pixels is the cell's mean radiance L, and BRF = pi L / (E cos theta_sun).

Each view is rendered twice with different seeds, half the samples per pixel each: the
per-pixel differences give the Monte Carlo standard error of the mean. A pilot of 2 x 8 samples
per pixel estimates how many samples bring the BRF's standard error to TARGET (a fraction of
it, e.g. 0.001), a final pair of renders takes them. Writes OUT_JSON with each view's BRF, its
standard error, its samples and the time of its renders, pilot included (VIEWS: signed view
zeniths, comma-separated; default RAMI's principal plane, -75 to 75 every 2).
"""
import json
import math
import pathlib
import sys
import time

import bpy
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
RAMI = ROOT / "data" / "rami"
PERIOD = 100.0
SUN_ZENITH, SUN_AZIMUTH = 20.0, 90.0  # degrees; azimuth clockwise from north (+y)
LEAF_R, LEAF_T, SOIL = 0.4957, 0.4409, 0.159
GON = 12
PIXELS = 100  # across the period, each way


def disc_mesh():
    """The sphere's 49,999 discs, each a 12-gon in its own plane."""
    d = np.loadtxt(RAMI / "het01_UNI_sphere.def")
    radius, centre, normal = d[:, 0], d[:, 1:4], d[:, 4:7]
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    helper = np.where(np.abs(normal[:, 2:3]) < 0.9, [[0.0, 0.0, 1.0]], [[1.0, 0.0, 0.0]])
    u = np.cross(normal, helper)
    u /= np.linalg.norm(u, axis=1)[:, None]
    v = np.cross(normal, u)
    angles = 2.0 * np.pi * np.arange(GON) / GON
    ring = (np.cos(angles)[None, :, None] * u[:, None, :] + np.sin(angles)[None, :, None] * v[:, None, :])
    # The circumradius of a regular 12-gon of the disc's area: 12/2 R^2 sin(30 deg) = pi r^2.
    scale = math.sqrt(math.pi / (GON / 2.0 * math.sin(2.0 * math.pi / GON)))
    vertices = (centre[:, None, :] + (scale * radius)[:, None, None] * ring).reshape(-1, 3)
    n = len(d)
    mesh = bpy.data.meshes.new("het01_sphere")
    mesh.vertices.add(len(vertices))
    mesh.vertices.foreach_set("co", vertices.astype(np.float32).ravel())
    mesh.loops.add(n * GON)
    mesh.loops.foreach_set("vertex_index", np.arange(n * GON, dtype=np.int32))
    mesh.polygons.add(n)
    mesh.polygons.foreach_set("loop_start", np.arange(0, n * GON, GON, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(n, GON, dtype=np.int32))
    mesh.update()
    mesh.validate()
    return mesh


def material(name, build):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    links.new(build(nodes, links).outputs[0], out.inputs["Surface"])
    return m


def leaf(nodes, links):
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (LEAF_R, LEAF_R, LEAF_R, 1.0)
    translucent = nodes.new("ShaderNodeBsdfTranslucent")
    translucent.inputs["Color"].default_value = (LEAF_T, LEAF_T, LEAF_T, 1.0)
    add = nodes.new("ShaderNodeAddShader")
    links.new(diffuse.outputs[0], add.inputs[0])
    links.new(translucent.outputs[0], add.inputs[1])
    return add


def soil(nodes, links):
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (SOIL, SOIL, SOIL, 1.0)
    return diffuse


def build_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    sphere = bpy.data.objects.new("sphere", disc_mesh())
    sphere.data.materials.append(material("leaf", leaf))
    spheres = bpy.data.collections.new("spheres")
    spheres.objects.link(sphere)
    cell = bpy.data.collections.new("cell")
    for x, y, z in np.loadtxt(RAMI / "het01_UNI_instances.def"):
        e = bpy.data.objects.new("sphere_at", None)
        e.instance_type = "COLLECTION"
        e.instance_collection = spheres
        e.location = (x, y, z)
        cell.objects.link(e)
    for i in range(-3, 4):
        for j in range(-3, 4):
            e = bpy.data.objects.new("cell_at", None)
            e.instance_type = "COLLECTION"
            e.instance_collection = cell
            e.location = (i * PERIOD, j * PERIOD, 0.0)
            scene.collection.objects.link(e)
    bpy.ops.mesh.primitive_plane_add(size=7 * PERIOD)
    bpy.context.active_object.data.materials.append(material("soil", soil))

    sun = bpy.data.lights.new("sun", "SUN")
    sun.energy = 1.0  # W/m2 normal to the beam
    sun.angle = 0.0
    sun_object = bpy.data.objects.new("sun", sun)
    # A sun light shines along its local -z: turn -z to the beam's direction of travel.
    sun_object.rotation_euler = (math.radians(SUN_ZENITH), 0.0, math.radians(-SUN_AZIMUTH + 180.0))
    scene.collection.objects.link(sun_object)
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world

    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.max_bounces = c.diffuse_bounces = c.transmission_bounces = 1024
    c.transparent_max_bounces = 0
    c.min_light_bounces = 0
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.pixel_filter_type = "BOX"  # samples uniform over each pixel's area of the ground
    c.filter_width = 1.0
    c.caustics_reflective = c.caustics_refractive = False
    c.blur_glossy = 0.0
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.threads_mode = "AUTO"
    return scene


def place_camera(scene, zenith, azimuth):
    """An orthographic camera looking down along (zenith, azimuth), its image one period of the
    ground: 100 m across, 100 cos(zenith) m up the image (the period foreshortened)."""
    cam = bpy.data.cameras.new("view")
    cam.type = "ORTHO"
    cam.clip_end = 10000.0
    obj = bpy.data.objects.new("view", cam)
    scene.collection.objects.link(obj)
    scene.camera = obj
    z, a = math.radians(zenith), math.radians(azimuth)
    towards = np.array([math.sin(z) * math.sin(a), math.sin(z) * math.cos(a), math.cos(z)])
    obj.location = tuple(2000.0 * towards)
    # Local -z along -towards, the image's up in the vertical plane of the view.
    obj.rotation_euler = (z, 0.0, -a + math.pi)
    # Rows rounded down, the pixels made taller to fit (Blender's pixel aspect is at least 1).
    height = max(1, math.floor(PIXELS * math.cos(z)))
    scene.render.resolution_x, scene.render.resolution_y = PIXELS, height
    scene.render.resolution_percentage = 100
    cam.ortho_scale = PERIOD  # the larger side: the image's width
    scene.render.pixel_aspect_x = 1.0
    scene.render.pixel_aspect_y = (PERIOD * math.cos(z) / height) / (PERIOD / PIXELS)
    return obj


def render_mean(scene, seed, samples, path):
    scene.cycles.seed = seed
    scene.cycles.samples = samples
    scene.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(str(path))
    pixels = np.array(image.pixels[:], dtype=np.float64).reshape(-1, 4)[:, :3].mean(axis=1)
    bpy.data.images.remove(image)
    return pixels


def measure(scene, samples, out):
    """The view's BRF and its standard error from two renders of samples / 2 each."""
    a = render_mean(scene, 1, samples // 2, out.with_suffix(".a.exr"))
    b = render_mean(scene, 2, samples // 2, out.with_suffix(".b.exr"))
    k = math.pi / math.cos(math.radians(SUN_ZENITH))  # E = 1 W/m2
    # Each pixel's Monte Carlo variance of the mean of both: ((a - b) / 2)^2 on average.
    return k * 0.5 * (a + b).mean(), k * math.sqrt(np.sum(((a - b) / 2.0) ** 2)) / len(a)


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    out, target = pathlib.Path(args[0]), float(args[1])
    views = range(-75, 76, 2) if len(args) < 3 else [int(v) for v in args[2].split(",")]
    started = time.time()
    scene = build_scene()
    build_time = time.time() - started
    results = []
    for view in views:
        azimuth = SUN_AZIMUTH if view < 0 else SUN_AZIMUTH + 180.0
        camera = place_camera(scene, abs(view), azimuth)
        t0 = time.time()
        brf, se = measure(scene, 16, out)
        samples = max(16, 2 * math.ceil(1.1 * 16 * (se / (target * brf)) ** 2 / 2))
        brf, se = measure(scene, samples, out)
        elapsed = time.time() - t0
        bpy.data.objects.remove(camera)
        results.append({"view_zenith_deg": view, "brf": brf, "brf_se": se, "samples": samples,
                        "seconds": elapsed})
        print(f"cycles view {view:+d}: BRF {brf:.5f} +- {se:.5f} at {samples} spp ({elapsed:.1f} s)",
              flush=True)
    out.write_text(json.dumps({"target": target, "pixels": PIXELS, "build_seconds": build_time,
                               "seconds": time.time() - started, "directions": results}, indent=1))


main()
