#!/usr/bin/env python3
"""An independent evaluation of PROSPECT-D (Feret et al. 2017) for tests/renderer/spectra/prospect_test.cpp:
written from the papers (Jacquemoud and Baret 1990's plate model, Stern 1964's average
transmissivity, Stokes' equations for N - 1 plates), sharing no code with renderer/spectra/prospect.cpp;
the exponential integral E1 by its power series and continued fraction.

Usage: prospect_reference.py data/spectra/prospect_d_dataSpec_PDB.txt
Prints "N Cab Car Ant Cbrown Cw Cm wavelength R T" for a few leaves and wavelengths.
"""
import math
import sys


def e1(x):
    """Exponential integral E1(x), x > 0."""
    if x < 1.0:
        total, term = 0.0, 1.0
        for k in range(1, 60):
            term *= -x / k
            total -= term / k
        return -0.5772156649015329 - math.log(x) + total
    # Continued fraction (Lentz), good for x >= 1.
    b = x + 1.0
    c = 1e300
    d = 1.0 / b
    h = d
    for i in range(1, 200):
        a = -i * i
        b += 2.0
        d = 1.0 / (a * d + b)
        c = b + a / c
        delta = c * d
        h *= delta
        if abs(delta - 1.0) < 1e-15:
            break
    return h * math.exp(-x)


def tav(theta_deg, n):
    """Stern (1964): transmissivity of a plane dielectric surface averaged over incidence 0..theta."""
    s = math.sin(math.radians(theta_deg))
    n2 = n * n
    np_, nm = n2 + 1.0, n2 - 1.0
    a = (n + 1.0) ** 2 / 2.0
    k = -((n2 - 1.0) ** 2) / 4.0
    if theta_deg == 90.0:
        b1 = 0.0
    else:
        b1 = math.sqrt((s * s - np_ / 2.0) ** 2 + k)
    b2 = s * s - np_ / 2.0
    b = b1 - b2
    ts = (k * k / (6 * b ** 3) + k / b - b / 2) - (k * k / (6 * a ** 3) + k / a - a / 2)
    tp1 = -2 * n2 * (b - a) / np_ ** 2
    tp2 = -2 * n2 * np_ * math.log(b / a) / nm ** 2
    tp3 = n2 * (1 / b - 1 / a) / 2
    tp4 = 16 * n2 ** 2 * (n2 ** 2 + 1) * math.log((2 * np_ * b - nm ** 2) / (2 * np_ * a - nm ** 2)) / (np_ ** 3 * nm ** 2)
    tp5 = 16 * n2 ** 3 * (1 / (2 * np_ * b - nm ** 2) - 1 / (2 * np_ * a - nm ** 2)) / np_ ** 3
    return (ts + tp1 + tp2 + tp3 + tp4 + tp5) / (2 * s * s)


def leaf(row, N, cab, car, ant, brown, cw, cm):
    n = row[1]
    k = (cab * row[2] + car * row[3] + ant * row[4] + brown * row[5] + cw * row[6] + cm * row[7]) / N
    tau = 1.0 if k <= 0 else (1 - k) * math.exp(-k) + k * k * e1(k)
    t_a = tav(40.0, n)
    r_a = 1 - t_a
    t12 = tav(90.0, n)
    r12 = 1 - t12
    t21 = t12 / (n * n)
    r21 = 1 - t21
    den = 1 - r21 * r21 * tau * tau
    Ta = t_a * tau * t21 / den
    Ra = r_a + r21 * tau * Ta
    t = t12 * tau * t21 / den
    r = r12 + r21 * tau * t
    if r + t >= 1:
        Tsub = t / (t + (1 - t) * (N - 1))
        Rsub = 1 - Tsub
    else:
        D = math.sqrt((1 + r + t) * (1 + r - t) * (1 - r + t) * (1 - r - t))
        a = (1 + r * r - t * t + D) / (2 * r)
        b = (1 - r * r + t * t + D) / (2 * t)
        bn1 = b ** (N - 1)
        bn2 = bn1 * bn1
        Rsub = a * (bn2 - 1) / (a * a * bn2 - 1)
        Tsub = bn1 * (a * a - 1) / (a * a * bn2 - 1)
    den = 1 - Rsub * r
    return Ra + Ta * Rsub * t / den, Ta * Tsub / den


def main():
    rows = {}
    with open(sys.argv[1]) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = [float(x) for x in line.split()]
            rows[int(v[0])] = v
    leaves = [(1.5, 40, 8, 0, 0, 0.01, 0.009),   # the typical green leaf
              (1.2, 10, 6, 8, 0.5, 0.008, 0.006),  # an autumn leaf
              (2.2, 60, 12, 1, 0, 0.02, 0.012)]    # a thick, dark one
    for p in leaves:
        for wl in (450, 550, 670, 720, 800, 950):
            r, t = leaf(rows[wl], *p)
            print(" ".join(str(x) for x in p), wl, "%.6f %.6f" % (r, t))


if __name__ == "__main__":
    main()
