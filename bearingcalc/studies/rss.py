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
    points = np.repeat(center[None, :], 4 * d + 1, axis=0)
    for i in range(d):
        for j, offset in enumerate((step[i], -step[i], step[i] / 2, -step[i] / 2)):
            points[1 + 4 * i + j, i] += offset
    results, _ = study.evaluate(points)
    out: dict[str, dict[str, Any]] = {}
    for key in study.keys:
        values = np.asarray(results[key])
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
    return out
