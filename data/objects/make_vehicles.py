#!/usr/bin/env python3
"""Writes the example vehicles of landsim's objects example (docs/OBJECTS.md): a car and a
truck built from boxes and wheel prisms, as OBJ + MTL and, for the car, the same mesh as
glTF 2.0 (the test that both formats give the same image reads both).

Axes as glTF has them: y up, the front toward +z, +x on the vehicle's left; metres; the
origin on the ground under the vehicle's centre. Every face has its own vertices and flat
normals, so that the OBJ and the glTF hold exactly the same triangles.

Run from anywhere: python3 data/objects/make_vehicles.py
"""
import base64
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# name: (base colour (linear), MTL Ns). glTF roughness = (2 / (Ns + 2)) ** 0.25, as landsim
# translates Ns (modules/meshes/mesh_io.cpp).
MATERIALS = {
    "paint_red": ((0.30, 0.03, 0.02), 200.0),
    "paint_olive": ((0.10, 0.11, 0.05), 60.0),
    "canvas": ((0.14, 0.13, 0.08), 2.0),
    "glass": ((0.01, 0.012, 0.015), 1000.0),
    "tyre": ((0.025, 0.025, 0.025), 8.0),
    "chrome": ((0.25, 0.25, 0.25), 400.0),
}


class Mesh:
    def __init__(self):
        self.faces = []  # (material, [(x, y, z), ...] counter-clockwise seen from outside)

    def quad(self, mat, a, b, c, d):
        self.faces.append((mat, [a, b, c, d]))

    def box(self, mat, x0, x1, y0, y1, z0, z1, top=None, front=None):
        """Axis-aligned box; `top` and `front` (+z) may take other materials."""
        p = lambda x, y, z: (x, y, z)
        self.quad(top or mat, p(x0, y1, z0), p(x0, y1, z1), p(x1, y1, z1), p(x1, y1, z0))  # +y
        self.quad(mat, p(x0, y0, z0), p(x1, y0, z0), p(x1, y0, z1), p(x0, y0, z1))  # -y
        self.quad(front or mat, p(x0, y0, z1), p(x1, y0, z1), p(x1, y1, z1), p(x0, y1, z1))  # +z
        self.quad(mat, p(x1, y0, z0), p(x0, y0, z0), p(x0, y1, z0), p(x1, y1, z0))  # -z
        self.quad(mat, p(x1, y0, z1), p(x1, y0, z0), p(x1, y1, z0), p(x1, y1, z1))  # +x
        self.quad(mat, p(x0, y0, z0), p(x0, y0, z1), p(x0, y1, z1), p(x0, y1, z0))  # -x

    def wheel(self, x_in, x_out, z, r, sides=12):
        """A wheel as a prism about the x axis from x_in to x_out, touching y = 0."""
        ring = [(r + r * math.cos(2 * math.pi * k / sides), z + r * math.sin(2 * math.pi * k / sides))
                for k in range(sides)]
        s = 1 if x_out > x_in else -1
        for k in range(sides):
            (y0, z0), (y1, z1) = ring[k], ring[(k + 1) % sides]
            if s > 0:
                self.quad("tyre", (x_in, y0, z0), (x_in, y1, z1), (x_out, y1, z1), (x_out, y0, z0))
            else:
                self.quad("tyre", (x_in, y0, z0), (x_out, y0, z0), (x_out, y1, z1), (x_in, y1, z1))
        outer = [(x_out, y, zz) for (y, zz) in ring]
        inner = [(x_in, y, zz) for (y, zz) in reversed(ring)]
        self.faces.append(("tyre", outer if s > 0 else list(reversed(outer))))
        self.faces.append(("tyre", inner if s > 0 else list(reversed(inner))))
        # The hub: a smaller disc just outside the tyre's face.
        x_hub = x_out + 0.01 * s
        hub = [(x_hub, r + 0.5 * (y - r), z + 0.5 * (zz - z)) for (y, zz) in ring]
        self.faces.append(("chrome", hub if s > 0 else list(reversed(hub))))


def normal(pts):
    ax, ay, az = (pts[1][i] - pts[0][i] for i in range(3))
    bx, by, bz = (pts[2][i] - pts[0][i] for i in range(3))
    n = (ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx)
    l = math.sqrt(sum(c * c for c in n))
    return tuple(c / l for c in n)


def car():
    m = Mesh()
    m.box("paint_red", -0.9, 0.9, 0.30, 0.95, -2.2, 2.2)  # body
    m.box("glass", -0.78, 0.78, 0.95, 1.38, -1.25, 0.85, top="paint_red")  # cabin
    m.box("paint_red", -0.8, 0.8, 1.38, 1.45, -1.3, 0.9)  # roof
    for z in (-1.35, 1.35):
        m.wheel(0.72, 0.92, z, 0.32)
        m.wheel(-0.72, -0.92, z, 0.32)
    return m


def truck():
    m = Mesh()
    m.box("paint_olive", -1.0, 1.0, 0.55, 0.85, -3.7, 3.7)  # chassis
    m.box("paint_olive", -1.2, 1.2, 0.85, 2.7, 2.0, 3.75, front="glass")  # cab
    m.box("glass", -1.1, 1.1, 1.8, 2.55, 2.6, 3.76)  # side windows, windscreen band
    m.box("canvas", -1.25, 1.25, 0.95, 3.2, -3.7, 1.85)  # cargo box under canvas
    for z in (-2.9, -1.7, 2.7):
        m.wheel(0.85, 1.2, z, 0.5)
        m.wheel(-0.85, -1.2, z, 0.5)
    return m


def triangles(mesh):
    """Per material: vertices, normals, and a fan of triangles per face."""
    out = {}
    for mat, pts in mesh.faces:
        n = normal(pts)
        v, nn, idx = out.setdefault(mat, ([], [], []))
        base = len(v)
        v.extend(pts)
        nn.extend([n] * len(pts))
        for k in range(1, len(pts) - 1):
            idx.extend([base, base + k, base + k + 1])
    return out


def write_obj(name, mesh, what="vehicle", script="make_vehicles.py"):
    tri = triangles(mesh)
    with open(os.path.join(HERE, name + ".mtl"), "w") as f:
        f.write(f"# landsim example {what} materials (data/objects/{script})\n")
        for mat in tri:
            (r, g, b), ns = MATERIALS[mat]
            f.write(f"newmtl {mat}\nKd {r:.4f} {g:.4f} {b:.4f}\nNs {ns:.1f}\n\n")
    with open(os.path.join(HERE, name + ".obj"), "w") as f:
        f.write(f"# landsim example {what} '{name}' (data/objects/{script}): y up, "
                "front +z, metres\n")
        f.write(f"mtllib {name}.mtl\no {name}\n")
        base = 1
        for mat, (v, n, idx) in tri.items():
            for p in v:
                f.write("v {:.4f} {:.4f} {:.4f}\n".format(*p))
            for q in n:
                f.write("vn {:.6f} {:.6f} {:.6f}\n".format(*q))
            f.write(f"usemtl {mat}\n")
            for k in range(0, len(idx), 3):
                a, b, c = (base + idx[k + j] for j in range(3))
                f.write(f"f {a}//{a} {b}//{b} {c}//{c}\n")
            base += len(v)


def write_gltf(name, mesh):
    tri = triangles(mesh)
    blob = bytearray()
    views, accessors, primitives, materials = [], [], [], []
    # The OBJ's numbers, rounded as it writes them, so both files hold the same mesh.
    rnd = lambda p, d: tuple(float(f"{c:.{d}f}") for c in p)
    for mat, (v, n, idx) in tri.items():
        (r, g, b), ns = MATERIALS[mat]
        materials.append({"name": mat, "pbrMetallicRoughness": {
            "baseColorFactor": [float(f"{r:.4f}"), float(f"{g:.4f}"), float(f"{b:.4f}"), 1.0],
            "metallicFactor": 0.0, "roughnessFactor": (2.0 / (ns + 2.0)) ** 0.25}})
        attrs = {}
        for key, data, digits in (("POSITION", v, 4), ("NORMAL", n, 6)):
            values = [rnd(p, digits) for p in data]
            off = len(blob)
            for p in values:
                blob += struct.pack("<3f", *p)
            views.append({"buffer": 0, "byteOffset": off, "byteLength": 12 * len(values)})
            acc = {"bufferView": len(views) - 1, "componentType": 5126, "count": len(values),
                   "type": "VEC3"}
            if key == "POSITION":
                acc["min"] = [min(p[i] for p in values) for i in range(3)]
                acc["max"] = [max(p[i] for p in values) for i in range(3)]
            accessors.append(acc)
            attrs[key] = len(accessors) - 1
        off = len(blob)
        for i in idx:
            blob += struct.pack("<I", i)
        views.append({"buffer": 0, "byteOffset": off, "byteLength": 4 * len(idx)})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5125,
                          "count": len(idx), "type": "SCALAR"})
        primitives.append({"attributes": attrs, "indices": len(accessors) - 1,
                           "material": len(materials) - 1})
    doc = {"asset": {"version": "2.0", "generator": "landsim data/objects/make_vehicles.py"},
           "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": name}],
           "meshes": [{"name": name, "primitives": primitives}], "materials": materials,
           "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                        + base64.b64encode(bytes(blob)).decode()}],
           "bufferViews": views, "accessors": accessors}
    with open(os.path.join(HERE, name + ".gltf"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    write_obj("car", car())
    write_gltf("car", car())
    write_obj("truck", truck())
