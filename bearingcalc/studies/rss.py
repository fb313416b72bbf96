"""RSS: the first-order spread of every result from the spreads of the inputs."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from bearingcalc.studies.study import Study


def rss(study: Study) -> dict[str, dict[str, Any]]:
    """First-order propagation: std = sqrt(Σ(∂f/∂xᵢ·σᵢ)²) at the distribution means.

    Derivatives are central differences with one Richardson step (error of
    order h⁴), all 4d + 1 designs in one solver call; h = σᵢ/100.
    """
    d = len(study.inputs)
    center = np.array([i.tolerance.center for i in study.inputs])
    sigma = np.array([i.tolerance.std for i in study.inputs])
    step = np.where(sigma > 0, sigma * 1e-2, 0.0)
    points = np.repeat(center[None, :], 6 * d + 1, axis=0)
    for i in range(d):
        for j, offset in enumerate((step[i], -step[i], step[i] / 2, -step[i] / 2)):
            points[1 + 4 * i + j, i] += offset
        # the band's ends, to find the switches RSS linearises across
        points[1 + 4 * d + 2 * i, i] = study.inputs[i].low
        points[2 + 4 * d + 2 * i, i] = study.inputs[i].high
    results, status = study.evaluate(points)
    switches = _switches(study, results, status, d)
    out: dict[str, dict[str, Any]] = {}
    for key in study.keys:
        values = np.broadcast_to(results[key], (6 * d + 1,))[:4 * d + 1]
        if not np.isfinite(values).all():
            # A result unbounded or impossible near the centre has no first-order spread.
            out[key] = {"mean": None, "std": None, "contributions": {}}
            continue
        derivatives = np.zeros(d)
        for i in range(d):
            if step[i] == 0:
                continue
            f_up, f_down, f_up2, f_down2 = values[1 + 4 * i: 5 + 4 * i]
            coarse = (f_up - f_down) / (2 * step[i])
            fine = (f_up2 - f_down2) / step[i]
            derivatives[i] = (4 * fine - coarse) / 3
        terms = (derivatives * sigma) ** 2
        total = float(terms.sum())
        mean = float(values[0])
        if not (np.isfinite(mean) and np.isfinite(total)):
            out[key] = {"mean": None, "std": None, "contributions": {}}
            continue
        shares = terms / total if total > 0 else np.zeros(d)
        out[key] = {
            "mean": mean,
            "std": math.sqrt(total),
            "contributions": {item.name: float(shares[i])
                              for i, item in enumerate(study.inputs)},
            "sensitivities": {item.name: float(derivatives[i])
                              for i, item in enumerate(study.inputs)},
        }
        if switches:
            out[key]["switches"] = switches
    return out


def _switches(study: Study, results: dict[str, Any], status: Any, d: int) -> list[str]:
    """The steps a design crosses within the tolerance band, which a linearisation at
    the centre cannot see: a result that stays put about the centre (a factor chosen by
    a table, a load case) but differs at an end of some input's band, or a design that
    becomes impossible there."""
    found = []
    ends = slice(4 * d + 1, 6 * d + 1)
    for key in study.keys:
        values = np.broadcast_to(results[key], (6 * d + 1,))
        near, far = values[:4 * d + 1], values[ends]
        if np.all(near == near[0]) and np.isfinite(near[0]) and np.any(
                np.isfinite(far) & (far != near[0])):
            found.append(key)
    if np.any(np.broadcast_to(status, (6 * d + 1,))[ends] != 0):
        found.append("the design becomes impossible")
    return found
