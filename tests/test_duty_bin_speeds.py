"""A duty-cycle bin's speed in either form: a bin's ring speeds replace the spec's
``speed`` and a bin's ``speed`` the spec's ring speeds, as a bin's torque replaces a
spec's power. Each bin is checked against the single-point spec written with that bin's
loads and speeds, and the cycle's Miner life against the bins' lives combined here."""

from __future__ import annotations

import math

import pytest

from tests.conftest import solve_json

COMMON = """kind: rolling-bearing
type: deep-groove
dynamic_load_rating: 55.3 kN
static_load_rating: 31.5 kN
static_factor: 13
pitch_diameter: 72.5 mm
lubrication:
  viscosity: 20 mm^2/s
contamination_factor: 0.5
"""
#: the bins as (the bin's fields, the single point's speed lines for that bin)
BINS = [
    ({"time": "30 %", "radial_load": "8 kN", "axial_load": "1 kN"}, None),
    ({"time": "70 %", "radial_load": "5 kN", "axial_load": "0.5 kN",
      "inner_speed": "900 rpm"}, "inner_speed: 900 rpm\n"),
]


def _spec(speed_lines: str, bins=None, loads: dict | None = None) -> str:
    text = COMMON + speed_lines
    for key, value in (loads or {}).items():
        text += f"{key}: {value}\n"
    if bins is not None:
        text += "duty_cycle:\n" + "".join(
            "  - {" + ", ".join(f"{k}: {v}" for k, v in item.items()) + "}\n"
            for item in bins)
    return text


@pytest.mark.parametrize("spec_speed", ["speed: 1500 rpm\n",
                                        "inner_speed: 1500 rpm\nouter_speed: 0 rpm\n"])
def test_a_bin_gives_its_speed_in_the_other_form(cli, spec_file, spec_speed):
    cycle = solve_json(cli, spec_file(_spec(spec_speed, [item for item, _ in BINS])))[0]
    lives, shares = [], []
    for k, (item, own_speed) in enumerate(BINS, 1):
        loads = {key: item[key] for key in ("radial_load", "axial_load")}
        single = solve_json(cli, spec_file(_spec(own_speed or spec_speed, loads=loads),
                                           name=f"bin{k}.yaml"))[0]["results"]
        life = single["modified_rating_life"]
        assert math.isclose(cycle["results"][f"duty_{k}_modified_rating_life"], life,
                            rel_tol=1e-9)
        lives.append(life)
        shares.append(float(item["time"].split()[0]) / 100)
    # Palmgren–Miner in hours: 1/L = Σ share_k / L_k
    miner = 1 / sum(share / life for share, life in zip(shares, lives, strict=True))
    assert math.isclose(cycle["results"]["modified_rating_life"], miner, rel_tol=1e-9)
