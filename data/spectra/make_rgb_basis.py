#!/usr/bin/python3
"""Derives rgb_basis.csv: three reflectance spectra B_r, B_g, B_b on landsim's spectral bins
that turn a linear Rec. 709 colour (r, g, b) into the reflectance r B_r + g B_g + b B_b.

The construction is the one of Mallett and Yuksel, "Spectral Primary Decomposition for
Rendering with sRGB Reflectance", EGSR 2019: the three spectra are non-negative, sum to one
at every wavelength (so any colour in [0, 1]^3 becomes a reflectance in [0, 1]), and each
reproduces its primary exactly; among such spectra the smoothest (least squared difference
between neighbouring bins) is taken. Reference light: a black body at 6504 K, the correlated
colour temperature of D65, Rec. 709's white (the CIE D65 table itself is not in the
project); "reproduces" means: the spectrum's colour under that light, divided channel by
channel by the light's own colour, is the primary. (Under equal energy no such spectra
exist: the constraints are infeasible below about 6000 K on these bins.) Computed here on landsim's 32 bins of 20 nm from 380 nm
(renderer/spectrum.h); past 780 nm every spectrum keeps its last visible value (the
visible primaries say nothing of the near infrared: docs/SPECTRAL.md).

Colour-matching functions: the fit of Wyman, Sloan and Shirley (JCGT 2013), as the renderer
uses them, integrated over each bin at 1 nm. Needs numpy and scipy (Debian: python3-scipy).
Run: /usr/bin/python3 data/spectra/make_rgb_basis.py > data/spectra/rgb_basis.csv
"""
import numpy as np
from scipy.optimize import minimize

BINS, START, STEP, VISIBLE = 32, 380.0, 20.0, 20  # bins 0-19 end at 780 nm


def lobe(l, c, a, b):
    t = (l - c) / np.where(l < c, a, b)
    return np.exp(-0.5 * t * t)


def xyz_bar(l):
    x = 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) \
        - 0.065 * lobe(l, 501.1, 20.4, 26.2)
    y = 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1)
    z = 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8)
    return np.stack([x, y, z], axis=-1)


TO_709 = np.array([[3.2404542, -1.5371385, -0.4985314],
                   [-0.9692660, 1.8760108, 0.0415560],
                   [0.0556434, -0.2040259, 1.0572252]])



def planck(l, kelvin):
    """Spectral radiance of a black body, arbitrary scale; l in nm."""
    m = l * 1e-9
    return 1.0 / (m ** 5 * (np.exp(1.4388e-2 / (m * kelvin)) - 1.0))


# Rec. 709 weight of each bin under the reference light: the functions times the light,
# integrated over the bin (1 nm midpoint sums).
weights = np.zeros((BINS, 3))
for k in range(BINS):
    l = START + STEP * k + 0.5 + np.arange(int(STEP))
    weights[k] = TO_709 @ (xyz_bar(l) * planck(l, 6504.0)[:, None]).sum(axis=0)
# Past the visible bins the spectra hold their last value: fold those bins' weights in.
w = weights[:VISIBLE].copy()
w[VISIBLE - 1] += weights[VISIBLE:].sum(axis=0)
white = w.sum(axis=0)  # the reference light's own colour
w = w / white  # each channel relative to the light's: white becomes (1, 1, 1)


def unpack(x):
    r, g = x[:VISIBLE], x[VISIBLE:]
    return r, g, 1.0 - r - g


def roughness(x):
    return sum(float(np.sum(np.diff(s) ** 2)) for s in unpack(x))


constraints = [
    {"type": "eq", "fun": lambda x: unpack(x)[0] @ w - np.array([1.0, 0.0, 0.0])},
    {"type": "eq", "fun": lambda x: unpack(x)[1] @ w - np.array([0.0, 1.0, 0.0])},
    {"type": "ineq", "fun": lambda x: unpack(x)[2]},  # B_b >= 0
]
x0 = np.full(2 * VISIBLE, 1.0 / 3.0)
result = minimize(roughness, x0, method="SLSQP", bounds=[(0.0, 1.0)] * (2 * VISIBLE),
                  constraints=constraints, options={"maxiter": 2000, "ftol": 1e-14})
assert result.success, result.message
r, g, b = (np.clip(s, 0.0, 1.0) for s in unpack(result.x))
print("# Rec. 709 primaries as reflectance spectra (data/spectra/make_rgb_basis.py): bin start nm, B_r, B_g, B_b")
print("nm,r,g,b")
for k in range(BINS):
    j = min(k, VISIBLE - 1)
    print(f"{START + STEP * k:.0f},{r[j]:.6f},{g[j]:.6f},{b[j]:.6f}")
