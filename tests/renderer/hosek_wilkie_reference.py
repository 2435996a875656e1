#!/usr/bin/env python3
"""An independent evaluation of the published Hosek-Wilkie tables (data/sky/), for
tests/renderer/atmosphere/hosek_wilkie_test.cpp: written from the papers and the data's README, sharing
no code with renderer/atmosphere/hosek_wilkie.cpp.

Prints, one per line:
  sky  elevation_deg turbidity albedo theta_deg gamma_deg R G B   (cd/m2-scaled Rec. 709)
  sun  elevation_deg turbidity E_R E_G E_B                        (lux-scaled, disc of 0.00465 rad)
"""
import csv
import math
import os
import sys


def read_sky(folder, stem):
    """{(channel, albedo, turbidity): [control point rows]} from the coefficient and radiance files."""
    coefficients, radiance = {}, {}
    with open(os.path.join(folder, stem + "_coefficients.csv")) as f:
        for row in csv.DictReader(f):
            key = (row["channel"], int(row["albedo"]), int(row["turbidity"]))
            coefficients.setdefault(key, {})[int(row["control_point"])] = [
                float(row["c%d" % i]) for i in range(9)]
    with open(os.path.join(folder, stem + "_radiance.csv")) as f:
        for row in csv.DictReader(f):
            key = (row["channel"], int(row["albedo"]), int(row["turbidity"]))
            radiance.setdefault(key, {})[int(row["control_point"])] = float(row["radiance"])
    return coefficients, radiance


def bernstein5(points, t):
    weights = [math.comb(5, i) * (1 - t) ** (5 - i) * t ** i for i in range(6)]
    return sum(w * p for w, p in zip(weights, points))


def sky_parameters(coefficients, radiance, channel, elevation, turbidity, albedo):
    t = (elevation / (math.pi / 2)) ** (1.0 / 3.0)
    low = int(math.floor(turbidity))
    high = min(low + 1, 10)
    frac = turbidity - low

    def one(a, turb):
        rows = coefficients[(channel, a, turb)]
        params = [bernstein5([rows[c][p] for c in range(6)], t) for p in range(9)]
        lm = bernstein5([radiance[(channel, a, turb)][c] for c in range(6)], t)
        return params + [lm]

    def by_albedo(turb):
        zero, one_ = one(0, turb), one(1, turb)
        return [(1 - albedo) * z + albedo * o for z, o in zip(zero, one_)]

    lo, hi = by_albedo(low), by_albedo(high)
    return [(1 - frac) * a + frac * b for a, b in zip(lo, hi)]


def perez_extended(p, theta, gamma):
    A, B, C, D, E, F, G, I, H = p[:9]
    chi = (1 + math.cos(gamma) ** 2) / (1 + H * H - 2 * H * math.cos(gamma)) ** 1.5
    return (1 + A * math.exp(B / (math.cos(theta) + 0.01))) * (
        C + D * math.exp(E * gamma) + F * math.cos(gamma) ** 2 + G * chi +
        I * math.sqrt(math.cos(theta)))


def lobe(x, mu, s1, s2):
    s = s1 if x < mu else s2
    return math.exp(-0.5 * ((x - mu) / s) ** 2)


def cmf(l):
    # Wyman, Sloan and Shirley 2013, multi-lobe fit.
    return (1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
            0.065 * lobe(l, 501.1, 20.4, 26.2),
            0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1),
            1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8))


def read_sun(folder):
    solar, limb = {}, {}
    with open(os.path.join(folder, "hosek_wilkie_solar_radiance.csv")) as f:
        for row in csv.DictReader(f):
            key = (int(row["wavelength_nm"]), int(row["turbidity"]), int(row["segment"]))
            solar.setdefault(key, [0.0] * 4)[int(row["control_point"])] = float(row["value"])
    with open(os.path.join(folder, "hosek_wilkie_limb_darkening.csv")) as f:
        for row in csv.DictReader(f):
            limb[int(row["wavelength_nm"])] = [float(row["c%d" % i]) for i in range(6)]
    return solar, limb


def sun_irradiance(solar, limb, elevation, turbidity, radius):
    k = min(int(45 * (elevation / (math.pi / 2)) ** (1.0 / 3.0)), 44)
    x = elevation - (k / 45.0) ** 3 * math.pi / 2
    low = int(math.floor(turbidity))
    high = min(low + 1, 10)
    frac = turbidity - low

    def centre(wl, turb):
        c3, c2, c1, c0 = solar[(wl, turb, k)]
        return c0 + c1 * x + c2 * x * x + c3 * x ** 3

    # Disc integral of L cos: pi sin^2 R x 2 int_0^1 L(mu) mu dmu, the limb polynomial
    # integrated exactly: 2 sum c_i / (i + 2).
    per_wavelength = {}
    for wl in range(320, 721, 40):
        disc_mean = 2 * sum(c / (i + 2) for i, c in enumerate(limb[wl]))
        per_wavelength[wl] = ((1 - frac) * centre(wl, low) + frac * centre(wl, high)) * disc_mean

    def spectral(l):
        l = min(max(l, 320.0), 720.0)
        i = min(int((l - 320) // 40), 9)
        f = (l - 320 - 40 * i) / 40
        return (1 - f) * per_wavelength[320 + 40 * i] + f * per_wavelength[360 + 40 * i]

    X = Y = Z = 0.0
    for l in range(360, 831):
        s = spectral(float(l))
        xb, yb, zb = cmf(float(l))
        X, Y, Z = X + s * xb, Y + s * yb, Z + s * zb
    solid = math.pi * math.sin(radius) ** 2 * 683.0
    X, Y, Z = X * solid, Y * solid, Z * solid
    return (3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z,
            -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z,
            0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z)


def main():
    folder = sys.argv[1]
    coefficients, radiance = read_sky(folder, "hosek_wilkie_rgb")
    solar, limb = read_sun(folder)
    albedo = 0.2
    for elevation_deg in (3.0, 12.0, 30.0, 55.0, 80.0):
        e = math.radians(elevation_deg)
        for turbidity in (2.0, 4.5, 9.0):
            params = {c: sky_parameters(coefficients, radiance, c, e, turbidity, albedo)
                      for c in "RGB"}
            # 20 directions: five view elevations at four azimuths from the sun.
            for view_elevation in (1.0, 8.0, 25.0, 50.0, 85.0):
                for azimuth in (0.0, 50.0, 110.0, 180.0):
                    v, a = math.radians(view_elevation), math.radians(azimuth)
                    cos_gamma = (math.sin(v) * math.sin(e) +
                                 math.cos(v) * math.cos(e) * math.cos(a))
                    gamma = math.acos(max(-1.0, min(1.0, cos_gamma)))
                    theta = math.pi / 2 - v
                    rgb = [perez_extended(params[c], theta, gamma) * params[c][9] * 683.0
                           for c in "RGB"]
                    print("sky %.17g %.17g %.17g %.17g %.17g %.9g %.9g %.9g" %
                          (elevation_deg, turbidity, albedo, math.degrees(theta),
                           math.degrees(gamma), *rgb))
            rgb = sun_irradiance(solar, limb, e, turbidity, 0.00465)
            print("sun %.17g %.17g %.9g %.9g %.9g" % (elevation_deg, turbidity, *rgb))


if __name__ == "__main__":
    main()
