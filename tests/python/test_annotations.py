"""Aerial annotations of a nadir map view read as their own tools read them: DOTA's labelTxt as
its devkit parses it, YOLO-OBB's labels as Ultralytics' format defines them, Pascal VOC's XML as
torchvision's VOCDetection parses it (xml.etree). Each box is checked against the target layer
read by OpenImageIO and against the truck's stated heading, nothing taken from landsim's code."""
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from conftest import read_exr, run_cli, source_path

HEADING = 30.0  # degrees clockwise from north; the map has north up


@pytest.fixture(scope="module")
def aerial_set(tmp_path_factory):
    out = tmp_path_factory.mktemp("aerial")
    scenario = out / "aerial.toml"
    scenario.write_text(f"""
[terrain]
elevation = "{source_path('data', 'terrain', 'volcano.asc')}"
[sun]
elevation = 50
azimuth = 160
[[views]]
name = "map"
projection = "orthographic"
position = [300.0, 700.0, 400.0]
extent = [24.0, 16.0]
width = 96
height = 64
[render]
spp = 2
[[objects]]
name = "truck"
file = "{source_path('data', 'objects', 'truck.obj')}"
position = [300.0, 700.0]
heading = {HEADING}
""")
    run_cli("render", str(scenario), "--out", str(out / "set"))
    run_cli("annotate", str(out / "set"), "--format", "dota,yolo-obb,voc")
    return out / "set"


def dota_objects(path):
    """DOTA_devkit's parse_dota_poly: lines of fewer than 9 fields (imagesource, gsd) skipped."""
    objects = []
    for line in open(path):
        fields = line.strip().split(" ")
        if len(fields) < 9:
            continue
        objects.append({"name": fields[8],
                        "difficult": fields[9] if len(fields) >= 10 else "0",
                        "poly": [(float(fields[2 * i]), float(fields[2 * i + 1]))
                                 for i in range(4)]})
    return objects


def target_pixels(set_dir):
    target = read_exr(set_dir / "map.exr")["target"]
    ys, xs = np.nonzero(target == 1)
    assert len(xs) > 50
    return xs, ys


def test_dota_box_holds_the_truck_and_starts_at_its_head(aerial_set):
    text = open(aerial_set / "dota" / "labelTxt" / "map.txt").read().splitlines()
    assert text[0] == "imagesource:landsim"
    assert text[1] == f"gsd:{24.0 / 96:g}"  # metres a pixel of the map
    (truck,) = dota_objects(aerial_set / "dota" / "labelTxt" / "map.txt")
    assert truck["name"] == "truck" and truck["difficult"] == "0"
    poly = np.array(truck["poly"])
    edges = np.roll(poly, -1, axis=0) - poly
    # Clockwise as seen (image y down): a positive shoelace sum.
    area = 0.5 * np.sum(poly[:, 0] * np.roll(poly[:, 1], -1) - np.roll(poly[:, 0], -1) * poly[:, 1])
    assert area > 0
    # Every target pixel's square inside.
    xs, ys = target_pixels(aerial_set)
    for dx, dy in ((0, 0), (1, 0), (0, 1), (1, 1)):
        px, py = xs + dx, ys + dy
        for p, e in zip(poly, edges):
            side = (e[0] * (py - p[1]) - e[1] * (px - p[0])) / np.hypot(*e)
            assert side.min() > -0.01
    # No rectangle at any angle (0.25-degree steps) around the pixels is smaller.
    corners = np.concatenate([np.stack([xs + dx, ys + dy], 1)
                              for dx, dy in ((0, 0), (1, 0), (0, 1), (1, 1))]).astype(float)
    least = min(np.ptp(corners @ [math.cos(a), math.sin(a)]) *
                np.ptp(corners @ [-math.sin(a), math.cos(a)])
                for a in np.radians(np.arange(0.0, 90.0, 0.25)))
    assert area <= least + 1e-6
    # The first side faces the truck's front: heading 30 clockwise from north (image up).
    front = np.array([math.sin(math.radians(HEADING)), -math.cos(math.radians(HEADING))])
    middles = 0.5 * (poly + np.roll(poly, -1, axis=0)) - poly.mean(axis=0)
    assert np.argmax(middles @ front) == 0
    # Its sides lie along the truck: the long one within a few degrees of the heading.
    long_side = edges[np.argmax(np.hypot(edges[:, 0], edges[:, 1]))]
    angle = math.degrees(math.atan2(long_side[0], -long_side[1])) % 180.0
    assert abs((angle - HEADING + 90.0) % 180.0 - 90.0) < 4.0


def test_yolo_obb_corners_are_dotas_over_the_image_size(aerial_set):
    (truck,) = dota_objects(aerial_set / "dota" / "labelTxt" / "map.txt")
    rows = [line.split() for line in open(aerial_set / "yolo-obb" / "labels" / "map.txt")]
    assert len(rows) == 1 and len(rows[0]) == 9  # class x1 y1 ... x4 y4
    classes = open(aerial_set / "yolo-obb" / "classes.txt").read().split()
    assert classes[int(rows[0][0])] == "truck"
    xy = np.array(rows[0][1:], dtype=float).reshape(4, 2)
    assert np.allclose(xy * [96, 64], truck["poly"], atol=0.01)
    assert 0.0 <= xy.min() and xy.max() <= 1.0


def parse_voc_xml(node):
    """torchvision.datasets.VOCDetection.parse_voc_xml."""
    voc_dict = {}
    children = list(node)
    if children:
        def_dic = {}
        for dc in map(parse_voc_xml, children):
            for ind, v in dc.items():
                def_dic.setdefault(ind, []).append(v)
        if node.tag == "annotation":
            def_dic["object"] = [def_dic["object"]]
        voc_dict = {node.tag: {ind: v[0] if len(v) == 1 else v for ind, v in def_dic.items()}}
    if node.text:
        text = node.text.strip()
        if not children:
            voc_dict[node.tag] = text
    return voc_dict


def test_voc_box_is_the_target_layers_extent_from_one(aerial_set):
    ids = open(aerial_set / "voc" / "ImageSets" / "Main" / "trainval.txt").read().split()
    assert ids == ["map"]
    ann = parse_voc_xml(ET.parse(aerial_set / "voc" / "Annotations" / "map.xml").getroot())
    a = ann["annotation"]
    assert a["filename"] == "map.png"
    assert (a["size"]["width"], a["size"]["height"], a["size"]["depth"]) == ("96", "64", "3")
    (obj,) = a["object"]
    assert obj["name"] == "truck" and obj["difficult"] == "0" and obj["truncated"] == "0"
    xs, ys = target_pixels(aerial_set)
    box = obj["bndbox"]
    assert [int(box[k]) for k in ("xmin", "ymin", "xmax", "ymax")] == [
        xs.min() + 1, ys.min() + 1, xs.max() + 1, ys.max() + 1]
