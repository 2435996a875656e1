#!/usr/bin/env python3
"""Writes the further object classes of landsim's detection examples (docs/OBJECTS.md): a
four-wheel-drive, a tracked vehicle, a person, a ridge tent, a cow and a hut, as OBJ + MTL,
built like the car and truck of make_vehicles.py (whose mesh writer they share): boxes,
prisms, cylinders and a low-poly ellipsoid, each face with its own vertices and flat normals.

Axes as glTF has them: y up, the front toward +z, +x on the object's left; metres; the origin
on the ground under the object's centre.

Run from anywhere: python3 data/objects/make_objects.py
"""
import math

import make_vehicles as mv

# Linear base colours and MTL Ns, added to the vehicles' (paint_olive, canvas, glass, tyre,
# chrome are theirs).
mv.MATERIALS.update({
    "paint_tan": ((0.24, 0.19, 0.11), 80.0),
    "track": ((0.03, 0.03, 0.028), 4.0),
    "skin": ((0.36, 0.22, 0.15), 6.0),
    "khaki": ((0.20, 0.18, 0.11), 2.0),
    "denim": ((0.05, 0.07, 0.12), 2.0),
    "tent_green": ((0.07, 0.11, 0.05), 4.0),
    "hide": ((0.16, 0.09, 0.05), 3.0),
    "hide_white": ((0.55, 0.53, 0.48), 3.0),
    "horn": ((0.45, 0.40, 0.30), 20.0),
    "wood": ((0.20, 0.13, 0.07), 3.0),
    "thatch": ((0.28, 0.22, 0.12), 1.0),
    "door": ((0.06, 0.04, 0.03), 3.0),
})


def centroid(pts):
    return tuple(sum(p[i] for p in pts) / len(pts) for i in range(3))


class Solid(mv.Mesh):
    """A mesh whose faces are turned to face away from a point inside their solid."""

    def face(self, mat, pts, inside):
        clean = [p for k, p in enumerate(pts) if p != pts[k - 1]]  # poles: drop repeats
        if len(clean) < 3:
            return
        n = mv.normal(clean)
        c = centroid(clean)
        if sum(n[i] * (c[i] - inside[i]) for i in range(3)) < 0:
            clean.reverse()
        self.faces.append((mat, clean))

    def cuboid(self, mat, x0, x1, y0, y1, z0, z1):
        self.box(mat, x0, x1, y0, y1, z0, z1)

    def cylinder(self, mat, a, b, r, sides=10):
        """A closed cylinder of radius r from point a to point b."""
        axis = tuple(b[i] - a[i] for i in range(3))
        length = math.sqrt(sum(c * c for c in axis))
        u = tuple(c / length for c in axis)
        helper = (1.0, 0.0, 0.0) if abs(u[0]) < 0.9 else (0.0, 1.0, 0.0)
        v = mv.normal([(0, 0, 0), u, helper])
        w = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        ring = lambda o: [tuple(o[i] + r * (math.cos(2 * math.pi * k / sides) * v[i] +
                                            math.sin(2 * math.pi * k / sides) * w[i])
                                for i in range(3)) for k in range(sides)]
        ra, rb = ring(a), ring(b)
        inside = centroid([a, b])
        for k in range(sides):
            self.face(mat, [ra[k], ra[(k + 1) % sides], rb[(k + 1) % sides], rb[k]], inside)
        self.face(mat, ra, inside)
        self.face(mat, rb, inside)

    def ellipsoid(self, mat, centre, radii, stacks=6, slices=10):
        pt = lambda i, j: tuple(
            centre[k] + radii[k] * c for k, c in enumerate((
                math.cos(math.pi * (i / stacks - 0.5)) * math.cos(2 * math.pi * j / slices),
                math.sin(math.pi * (i / stacks - 0.5)),
                math.cos(math.pi * (i / stacks - 0.5)) * math.sin(2 * math.pi * j / slices))))
        for i in range(stacks):
            for j in range(slices):
                self.face(mat, [pt(i, j), pt(i, j + 1), pt(i + 1, j + 1), pt(i + 1, j)], centre)

    def gable(self, mat, x0, x1, y0, y1, z0, z1):
        """A triangular prism along z: a ridge at x = (x0 + x1) / 2, y1, eaves at y0."""
        xm = 0.5 * (x0 + x1)
        inside = (xm, y0 + 0.3 * (y1 - y0), 0.5 * (z0 + z1))
        self.face(mat, [(x0, y0, z0), (x0, y0, z1), (xm, y1, z1), (xm, y1, z0)], inside)
        self.face(mat, [(x1, y0, z0), (xm, y1, z0), (xm, y1, z1), (x1, y0, z1)], inside)
        self.face(mat, [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)], inside)
        self.face(mat, [(x0, y0, z1), (x1, y0, z1), (xm, y1, z1)], inside)
        self.face(mat, [(x0, y0, z0), (xm, y1, z0), (x1, y0, z0)], inside)


def suv():
    """A four-wheel-drive: high body, tall cabin, a spare wheel on its tailgate."""
    m = Solid()
    m.box("paint_tan", -0.95, 0.95, 0.50, 1.15, -2.3, 2.3)
    m.box("glass", -0.85, 0.85, 1.15, 1.80, -2.2, 0.9, top="paint_tan")
    m.box("paint_tan", -0.88, 0.88, 1.80, 1.88, -2.25, 0.95)
    m.box("chrome", -0.8, 0.8, 1.88, 1.95, -1.8, 0.4)  # roof rack
    for z in (-1.45, 1.45):
        m.wheel(0.75, 0.98, z, 0.38)
        m.wheel(-0.75, -0.98, z, 0.38)
    m.cylinder("tyre", (0.0, 0.95, -2.3), (0.0, 0.95, -2.55), 0.36, sides=12)
    return m


def tracked():
    """A tracked vehicle: hull, turret and gun over two tracks with road wheels."""
    m = Solid()
    m.box("paint_olive", -1.25, 1.25, 0.45, 1.6, -3.3, 3.3)
    m.box("paint_olive", -1.05, 1.05, 1.6, 2.3, -1.3, 1.0)
    m.cylinder("paint_olive", (0.0, 1.95, 1.0), (0.0, 1.95, 5.0), 0.09)
    for side in (1, -1):
        x_in, x_out = 1.25 * side, 1.8 * side
        m.box("track", min(x_in, x_out), max(x_in, x_out), 0.0, 0.95, -3.5, 3.5)
        for z in (-2.6, -1.3, 0.0, 1.3, 2.6):
            m.wheel(x_out, x_out + 0.06 * side, z, 0.33)
    return m


def person():
    """A person 1.75 m tall, standing, facing +z."""
    m = Solid()
    for x in (0.1, -0.1):
        m.cylinder("denim", (x, 0.0, 0.0), (x, 0.86, 0.0), 0.075, sides=8)
        m.box("tyre", x - 0.06, x + 0.06, 0.0, 0.08, -0.06, 0.18)  # shoe
    m.box("khaki", -0.2, 0.2, 0.86, 1.45, -0.11, 0.11)
    for x in (0.26, -0.26):
        m.cylinder("khaki", (x, 1.42, 0.0), (x * 1.1, 0.82, 0.03), 0.055, sides=8)
    m.cylinder("skin", (0.0, 1.45, 0.0), (0.0, 1.53, 0.0), 0.055, sides=8)
    m.ellipsoid("skin", (0.0, 1.63, 0.01), (0.09, 0.12, 0.105))
    return m


def tent():
    """A ridge tent for two: 2.2 m long, 1.8 m wide, 1.2 m high."""
    m = Solid()
    m.gable("tent_green", -0.9, 0.9, 0.0, 1.2, -1.1, 1.1)
    return m


def cow():
    """A cow, 2.4 m long and 1.45 m at the shoulder, facing +z."""
    m = Solid()
    m.box("hide", -0.34, 0.34, 0.72, 1.38, -0.95, 0.85)
    m.box("hide_white", -0.345, 0.345, 0.85, 1.2, -0.5, 0.2)  # a patch on either flank
    for x in (0.22, -0.22):
        for z in (0.7, -0.8):
            m.box("hide", x - 0.07, x + 0.07, 0.0, 0.74, z - 0.07, z + 0.07)
    m.box("hide", -0.13, 0.13, 1.0, 1.4, 0.85, 1.15)  # neck
    m.box("hide_white", -0.14, 0.14, 0.95, 1.35, 1.15, 1.55)  # head
    for x in (0.12, -0.12):
        m.cylinder("horn", (x, 1.33, 1.25), (x * 2.2, 1.45, 1.22), 0.025, sides=6)
    m.cylinder("hide", (0.0, 1.3, -0.95), (0.0, 0.6, -1.05), 0.03, sides=6)  # tail
    return m


def hut():
    """A hut: wooden walls 4 x 3 m, a thatched gable roof to 3.6 m, a door on its front."""
    m = Solid()
    m.box("wood", -2.0, 2.0, 0.0, 2.2, -1.5, 1.5)
    m.box("door", -0.45, 0.45, 0.0, 1.9, 1.5, 1.53)
    m.gable("thatch", -2.35, 2.35, 2.0, 3.6, -1.85, 1.85)
    return m


if __name__ == "__main__":
    for name, make in (("suv", suv), ("tracked", tracked), ("person", person), ("tent", tent),
                       ("cow", cow), ("hut", hut)):
        mv.write_obj(name, make(), "object", "make_objects.py")
