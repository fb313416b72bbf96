"""kind: bevel-drive duty-cycle bins that set the bearings' oil (``temperature`` or
``viscosity``, as rolling-bearing bins do): each bin's bearings as a single-point drive
solve at that bin's torque, speed and oil, and the cycle's lives by Palmgren–Miner from
those."""

from __future__ import annotations

import math

import pytest

from tests.conftest import ROOT, solve_json

REL = 1e-9
#: specs/bevel-drive-duty-cycle.yaml without its bins, its oil given by its grade at a
#: temperature, or by its operating viscosity
EXAMPLE = (ROOT / "specs" / "bevel-drive-duty-cycle.yaml").read_text().split("duty_cycle:")[0]
GRADE_OIL = ("lubrication: {viscosity_40: 68 mm^2/s, viscosity_100: 8.7 mm^2/s, "
             "temperature: 70 degC}")
VISCOSITY_OIL = "lubrication: {viscosity: 68 mm^2/s}"
BASE = EXAMPLE.replace(VISCOSITY_OIL, GRADE_OIL)
BEARINGS = [f"{shaft}_bearing_{i}" for shaft in ("pinion", "gear") for i in (1, 2)]
#: (time share, torque, input speed, the bin's oil: a field of lubrication and its value)
BINS = [(0.05, "70 N*m", "300 rpm", ("temperature", "10 degC")),
        (0.80, "60 N*m", "1500 rpm", None),
        (0.10, "64 N*m", "1500 rpm", ("temperature", "95 degC")),
        (0.05, "120 N*m", "0 rpm", ("temperature", "40 degC"))]
VISCOSITY_BINS = [(0.3, "70 N*m", "300 rpm", ("viscosity", "320 mm^2/s")),
                  (0.7, "60 N*m", "1500 rpm", ("viscosity", "12 mm^2/s"))]


def _cycle(bins, base: str = BASE) -> str:
    lines = []
    for time, torque, speed, oil in bins:
        extra = f", {oil[0]}: {oil[1]}" if oil else ""
        lines.append(f"  - {{time: {100 * time:g} %, torque: {torque}, input_speed: {speed}"
                     f"{extra}}}\n")
    return base + "duty_cycle:\n" + "".join(lines)


def _point(torque: str, speed: str, oil, base: str = BASE) -> str:
    """The drive at one bin's torque, speed and oil, with no duty cycle."""
    text = base.replace("torque: 60 N*m ", f"torque: {torque} ").replace(
        "input_speed: 1500 rpm", f"input_speed: {speed}")
    if oil is None:
        return text
    field, value = oil
    own = "temperature: 70 degC" if field == "temperature" else "viscosity: 68 mm^2/s"
    return text.replace(own, f"{field}: {value}")


@pytest.mark.parametrize(("bins", "base"), [(BINS, BASE), (VISCOSITY_BINS, EXAMPLE)],
                         ids=["temperature", "viscosity"])
def test_each_bin_runs_on_its_own_oil(bins, base, cli, spec_file):
    (cycle,) = solve_json(cli, spec_file(_cycle(bins, base), "cycle.yaml"))
    points = []
    for k, (_, torque, speed, oil) in enumerate(bins, 1):
        if speed == "0 rpm":
            points.append(None)
            continue
        (point,) = solve_json(cli, spec_file(_point(torque, speed, oil, base), f"bin{k}.yaml"))
        points.append(point["results"])
        assert math.isclose(cycle["results"][f"duty_{k}_system_modified_rating_life"],
                            point["results"]["system_modified_rating_life"], rel_tol=REL)
    # 1/L = Σ tᵢ/Lᵢ over the bins that turn (the bin at rest does no damage)
    for name in BEARINGS:
        for key in ("modified_rating_life", "basic_rating_life"):
            damage = sum(time / point[f"{name}_{key}"]
                         for (time, *_), point in zip(bins, points, strict=True)
                         if point is not None)
            assert math.isclose(cycle["results"][f"{name}_{key}"], 1.0 / damage,
                                rel_tol=REL), (name, key)


def test_a_bins_oil_changes_the_modified_life_only(cli, spec_file):
    """The same bin cold and warm: the basic lives agree, the modified ones (κ, aISO) do
    not, and the cold oil (thicker film) gives the longer modified life here."""
    warm = [(0.5, "60 N*m", "1500 rpm", None), (0.5, "64 N*m", "1500 rpm", None)]
    cold = [warm[0], (0.5, "64 N*m", "1500 rpm", ("temperature", "30 degC"))]
    (a,), (b,) = (solve_json(cli, spec_file(_cycle(bins), f"{i}.yaml"))
                  for i, bins in enumerate((warm, cold)))
    for name in BEARINGS:
        assert math.isclose(a["results"][f"{name}_basic_rating_life"],
                            b["results"][f"{name}_basic_rating_life"], rel_tol=REL)
    assert b["results"]["duty_2_system_modified_rating_life"] > \
        a["results"]["duty_2_system_modified_rating_life"]


def test_a_bins_temperature_needs_the_oils_grade(cli, spec_file):
    path = spec_file(_cycle(BINS, EXAMPLE), "cycle.yaml")
    run = cli("solve", path)
    assert run.code == 2
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and "duty_cycle.1.temperature" in lines[0]
    assert "viscosity_40" in lines[0] and lines[0].startswith(f"{path}:")
