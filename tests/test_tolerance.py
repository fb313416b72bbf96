"""Tolerance studies against independent computations."""

from __future__ import annotations

import importlib
import json
import math
import re

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.stats import norm

from bearingcalc.core.thrust_bearing import solve_thrust_bearing
from bearingcalc.evaluation import parse_document
from bearingcalc.models.yaml_loader import load_documents
from bearingcalc.studies import BLOCK, HISTOGRAM_BINS, Study
from bearingcalc.studies.monte_carlo import monte_carlo
from bearingcalc.studies.rss import rss
from bearingcalc.studies.sampling import draw
from bearingcalc.studies.sensitivity import sobol_indices
from bearingcalc.studies.worst_case import refine_with_lbfgsb, worst_case
from tests.conftest import ROOT, study_status

TB = """kind: thrust-bearing
ball_diameter: 12.7 mm ± 0.005 mm
contact_angle: 30 deg ± 0.25 deg
pitch_radius: 26 mm ± 0.03 mm
shaft_speed: 1500 rpm
limits:
  max_spin_to_roll: 0.004
"""

# center_speed = R·Ω − r·ω (internal contact): linear in the two toleranced speeds.
R_RING, R_DISK = 0.08, 0.02
DISK = """kind: disk-on-circle
disk_radius: 20 mm
surface_radius: 80 mm
contact: internal
disk_speed: {disk}
surface_speed: {ring}
"""


def study_of(spec_file, text) -> Study:
    (document,) = load_documents(spec_file(text))
    kind, spec = parse_document(document)
    return Study(kind, spec)


def linear_disk(spec_file, disk="600 rad/s ± 6 rad/s", ring="-100 rad/s ± 3 rad/s"):
    return study_of(spec_file, DISK.format(disk=disk, ring=ring))


def test_worst_case_bounds_a_dense_grid_and_finds_the_interior_maximum(spec_file):
    study = study_of(spec_file, TB)
    wc = worst_case(study)
    d, theta, b = np.meshgrid(np.linspace(0.012695, 0.012705, 31),
                              np.radians(np.linspace(29.75, 30.25, 31)),
                              np.linspace(0.02597, 0.02603, 31), indexing="ij")
    grid = solve_thrust_bearing(d / 2, theta, b, 1500 * math.pi / 30, max_spin_to_roll=0.004)
    for key in ("spin_to_roll", "slip_margin", "ball_speed", "pitch_radius_max"):
        values = grid[key]
        # At least as extreme as every grid point, and no further than the grid allows.
        assert wc[key]["min"] <= values.min() + 1e-12 * abs(values.min())
        assert wc[key]["max"] >= values.max() - 1e-12 * abs(values.max())
        span = values.max() - values.min()
        assert wc[key]["min"] >= values.min() - 0.01 * span
        assert wc[key]["max"] <= values.max() + 0.01 * span
    # slip_margin = 0.004 − |ρ| peaks where ρ = 0, inside the box, not at a corner.
    assert_allclose(wc["slip_margin"]["max"], 0.004, rtol=1e-9)
    at = wc["slip_margin"]["max_inputs"]
    rho = solve_thrust_bearing(at["ball_diameter"] / 2, at["contact_angle"],
                               at["pitch_radius"], 1.0)["spin_to_roll"]
    assert abs(rho) < 1e-11


EXAMPLE_STUDIES = sorted((ROOT / "specs" / "tolerances").glob("*.yaml"))


def example_study(path) -> Study:
    (document,) = load_documents(path)
    kind, spec = parse_document(document)
    return Study(kind, spec)


def lbfgsb_worst_case(study: Study) -> dict[str, dict[str, float]]:
    """The extremes as L-BFGS-B finds them from the best of the same corners and Sobol
    points, for every result, monotonic or not: the search the zoom replaces."""
    low, width = study.box()
    unit = study.search_points()
    results, _ = study.evaluate(low + unit * width)
    found: dict[str, dict[str, float]] = {}
    for key in study.keys:
        for sense, sign in (("min", 1.0), ("max", -1.0)):
            start = unit[np.nanargmin(sign * results[key])]
            found.setdefault(key, {})[sense] = sign * refine_with_lbfgsb(study, key, sign,
                                                                         start, low, width)[1]
    return found


@pytest.mark.parametrize("path", EXAMPLE_STUDIES, ids=lambda p: p.stem)
def test_worst_case_is_as_extreme_as_lbfgsb_on_every_example(path):
    study = example_study(path)
    ours, reference = worst_case(study), lbfgsb_worst_case(study)
    for key, entry in reference.items():
        for sense in ("min", "max"):
            scale = max(abs(entry[sense]), abs(ours[key][sense]), 1e-300)
            # Never less extreme than L-BFGS-B beyond rounding, and never beyond the box
            # (both stay inside it, so neither can be more extreme by more than that).
            assert abs(ours[key][sense] - entry[sense]) <= 1e-13 * scale, (key, sense)
            inputs = ours[key][f"{sense}_inputs"]
            for item in study.inputs:
                assert item.low <= inputs[item.name] <= item.high


def test_a_monotonic_result_has_its_extremes_at_corners_exactly(spec_file):
    study = linear_disk(spec_file)
    wc = worst_case(study)["center_speed"]
    # center_speed = R·Ω − r·ω falls with ω and rises with Ω.
    assert wc["min"] == R_RING * -103 - R_DISK * 606
    assert wc["max"] == R_RING * -97 - R_DISK * 594
    assert wc["min_inputs"] == {"disk_speed": 606.0, "surface_speed": -103.0}


def test_extremes_with_many_free_inputs_go_to_lbfgsb(spec_file, monkeypatch):
    search = importlib.import_module("bearingcalc.studies.worst_case")
    study = study_of(spec_file, TB)
    zoomed = worst_case(study)
    refined_keys = []

    def counted(study, key, *args):
        refined_keys.append(key)
        return refine_with_lbfgsb(study, key, *args)

    monkeypatch.setattr(search, "GRID_MAX_FREE", 0)
    monkeypatch.setattr(search, "refine_with_lbfgsb", counted)
    refined = worst_case(study)
    assert "slip_margin" in refined_keys   # its maximum is inside the box: not monotonic
    for key in ("slip_margin", "ball_speed", "spin_to_roll"):
        for sense in ("min", "max"):
            assert_allclose(refined[key][sense], zoomed[key][sense], rtol=1e-12, atol=1e-18)


def test_the_default_study_imports_no_scipy_stats_special_or_optimize():
    import subprocess
    import sys

    code = ("import sys\nfrom bearingcalc.cli import app\n"
            "sys.argv = ['bearingcalc', 'tolerance', 'specs/tolerances/thrust-bearing.yaml',"
            " '-f', 'json']\n"
            "try:\n    app()\nexcept SystemExit:\n    pass\n"
            "print(sorted(m for m in ('scipy.stats', 'scipy.special', 'scipy.optimize')"
            " if m in sys.modules), file=sys.stderr)\n")
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                          text=True, check=False)
    assert done.stderr.strip().endswith("[]"), done.stderr


def test_histogram_bins_are_the_clipped_floors_on_both_counting_paths():
    from bearingcalc.studies import _Accumulator, _Scratch

    rng = np.random.default_rng(11)
    pilot = rng.normal(5.0, 1.0, BLOCK)
    accumulator = _Accumulator(5.0, pilot)
    inside = rng.uniform(pilot.min(), pilot.max(), BLOCK)            # the fast path
    outside = np.concatenate([rng.normal(5.0, 9.0, BLOCK - 2),       # both overflow bins
                              [accumulator.bins.edge, np.nextafter(accumulator.bins.edge, 0.0)]])
    scratch = _Scratch()
    for chunk in (inside, outside, np.full(BLOCK, 5.25)):
        accumulator.add(chunk, scratch)
    values = np.concatenate([inside, outside, np.full(BLOCK, 5.25)])
    index = np.floor((values - accumulator.bins.edge) * (1.0 / accumulator.bins.width))
    expected = np.bincount((np.clip(index, -1, HISTOGRAM_BINS) + 1).astype(np.int64),
                           minlength=HISTOGRAM_BINS + 2)
    assert np.array_equal(accumulator.bins.counts, expected)
    assert expected[0] > 0 and expected[-1] > 0


def test_rss_is_exact_for_a_linear_result(spec_file):
    study = linear_disk(spec_file)
    spread = rss(study)["center_speed"]
    sigma_disk, sigma_ring = 6 / 3, 3 / 3
    exact = math.hypot(R_RING * sigma_ring, R_DISK * sigma_disk)
    assert_allclose(spread["std"], exact, rtol=1e-9)
    assert_allclose(spread["mean"], R_RING * -100 - R_DISK * 600, rtol=1e-12)
    shares = spread["contributions"]
    assert_allclose(shares["surface_speed"], (R_RING * sigma_ring) ** 2 / exact**2, rtol=1e-9)


def test_rss_derivatives_match_plain_finite_differences(spec_file):
    study = study_of(spec_file, TB)
    spread = rss(study)["spin_to_roll"]
    center = {"d": 0.0127, "theta": math.radians(30), "b": 0.026}
    sigma = {"d": 0.005e-3 / 3, "theta": math.radians(0.25) / 3, "b": 0.03e-3 / 3}

    def rho(d, theta, b):
        return float(solve_thrust_bearing(d / 2, theta, b, 1.0)["spin_to_roll"])

    terms = []
    for name in center:
        h = 1e-3 * sigma[name]
        up, down = dict(center), dict(center)
        up[name] += h
        down[name] -= h
        terms.append(((rho(**up) - rho(**down)) / (2 * h) * sigma[name]) ** 2)
    assert_allclose(spread["std"], math.sqrt(sum(terms)), rtol=1e-6)


@pytest.mark.parametrize("distribution", ["normal", "uniform", "triangular"])
def test_monte_carlo_moments_of_a_linear_result_are_analytic(spec_file, distribution):
    disk = f"{{nominal: 600 rad/s, tolerance: 6 rad/s, distribution: {distribution}}}"
    study = linear_disk(spec_file, disk=disk)
    mc = monte_carlo(study, 1 << 17, keys=["center_speed"])
    stats = mc.stats["center_speed"]
    disk_std = {"normal": 2.0, "uniform": 12 / math.sqrt(12), "triangular": 12 / math.sqrt(24)}
    exact_std = math.hypot(R_RING * 1.0, R_DISK * disk_std[distribution])
    exact_mean = R_RING * -100 - R_DISK * 600
    assert abs(stats["mean"] - exact_mean) < 1e-3 * exact_std
    assert_allclose(stats["std"], exact_std, rtol=2e-3)


def test_monte_carlo_agrees_with_rss_for_small_tolerances(spec_file):
    small = TB.replace("0.005 mm", "0.00005 mm").replace("0.25 deg", "0.0025 deg").replace(
        "0.03 mm", "0.0003 mm")
    study = study_of(spec_file, small)
    spread = rss(study)["spin_to_roll"]
    mc = monte_carlo(study, 1 << 16, keys=["spin_to_roll"]).stats["spin_to_roll"]
    assert_allclose(mc["std"], spread["std"], rtol=5e-3)
    assert abs(mc["mean"] - spread["mean"]) < 1e-2 * spread["std"]


def test_yield_matches_the_analytic_probability(spec_file):
    # apex mismatch m = c·b − 1 with c = sinα/(a·sinβ): |m| <= L holds for b in
    # [(1 − L)/c, (1 + L)/c], and b is normal.
    text = """kind: bevel-gears
gear_a: {pitch_radius: 15 mm, pitch_angle: 30 deg}
gear_b: {pitch_radius: 26 mm ± 0.06 mm, pitch_angle: 60 deg}
arm_speed: 100 rpm
limits: {max_apex_mismatch: 0.001}
"""
    study = study_of(spec_file, text)
    mc = monte_carlo(study, 1 << 18, keys=["apex_mismatch"])
    c = math.sin(math.radians(30)) / (0.015 * math.sin(math.radians(60)))
    low, high = (1 - 0.001) / c, (1 + 0.001) / c
    sigma = 0.06e-3 / 3
    expected = norm.cdf((high - 0.026) / sigma) - norm.cdf((low - 0.026) / sigma)
    assert 0.2 < expected < 0.95
    assert abs(mc.yield_fraction - expected) < 2e-4
    assert_allclose(mc.ppm_out, 1e6 * (1 - mc.yield_fraction))


def test_sobol_indices_of_an_additive_function(spec_file):
    study = linear_disk(spec_file)
    indices = sobol_indices(study, 1 << 16)["center_speed"]
    variance = (R_RING * 1.0) ** 2 + (R_DISK * 2.0) ** 2
    expected = {"surface_speed": (R_RING * 1.0) ** 2 / variance,
                "disk_speed": (R_DISK * 2.0) ** 2 / variance}
    for name, value in expected.items():
        assert abs(indices["first_order"][name] - value) < 0.01
        assert abs(indices["total_order"][name] - value) < 0.01


@pytest.mark.parametrize("sampler", ["sobol", "random"])
def test_same_seed_same_answer_whatever_the_chunks_and_threads(spec_file, sampler):
    study = study_of(spec_file, TB)
    samples = 5 * BLOCK + 1234
    runs = [monte_carlo(study, samples, seed=7, sampler=sampler, chunk=chunk, threads=threads)
            for chunk, threads in ((BLOCK, 1), (4 * BLOCK, 2), (2 * BLOCK, 3))]
    for run in runs[1:]:
        assert run.stats == runs[0].stats
        assert run.passed == runs[0].passed
    other_seed = monte_carlo(study, samples, seed=8, sampler=sampler)
    assert other_seed.stats["spin_to_roll"]["mean"] != runs[0].stats["spin_to_roll"]["mean"]


def test_quantiles_are_within_one_histogram_bin_of_the_exact_ones(spec_file):
    study = study_of(spec_file, TB)
    samples = 3 * BLOCK
    mc = monte_carlo(study, samples, keys=["spin_to_roll"])
    values, _ = study.evaluate(draw(study.inputs, 0, samples, 0, "sobol"), ["spin_to_roll"])
    exact = values["spin_to_roll"]
    pilot = exact[:BLOCK]
    bin_width = 3 * (pilot.max() - pilot.min()) / HISTOGRAM_BINS
    stats = mc.stats["spin_to_roll"]
    for name, q in (("p00135", 0.00135), ("p50", 0.5), ("p99865", 0.99865)):
        assert abs(stats[name] - np.quantile(exact, q)) <= bin_width
    assert stats["min"] == exact.min() and stats["max"] == exact.max()
    assert_allclose(stats["mean"], exact.mean(), rtol=1e-12)
    assert_allclose(stats["std"], exact.std(ddof=1), rtol=1e-10)


def test_impossible_samples_count_as_out_of_spec_and_never_crash(spec_file):
    text = TB.replace("30 deg ± 0.25 deg", "44 deg ± 3 deg")
    study = study_of(spec_file, text)
    mc = monte_carlo(study, 1 << 16, keys=["spin_to_roll"])
    assert 0 < mc.infeasible < mc.samples
    assert mc.passed <= mc.samples - mc.infeasible
    assert all(v is None or math.isfinite(v) for v in mc.stats["spin_to_roll"].values())


# --- the command ---------------------------------------------------------------------------

CONTRACT_TOP = {"spec", "samples", "seed", "sampler", "inputs", "results", "yield", "ppm_out",
                "cpk", "units"}
TOLERANCED = sorted((ROOT / "specs" / "tolerances").glob("*.yaml"))


@pytest.mark.parametrize("spec", TOLERANCED, ids=lambda p: p.stem)
def test_every_kind_runs_every_method_with_sobol_in_json(cli, spec):
    run = cli("tolerance", spec, "--sobol", "--samples", "4096", "--format", "json")
    assert run.code == study_status(json.loads(run.out)), run.err
    record = json.loads(run.out)
    assert set(record) >= CONTRACT_TOP
    assert record["samples"] == 4096 and record["seed"] == 0 and record["sampler"] == "sobol"
    for entry in record["inputs"].values():
        assert set(entry) == {"nominal", "low", "high", "distribution", "std", "written_unit"}
    for key, entry in record["results"].items():
        assert {"nominal", "worst_case", "rss", "monte_carlo"} <= set(entry), key
        assert {"min", "max"} <= set(entry["worst_case"])
        assert {"mean", "std", "contributions"} <= set(entry["rss"])
        assert {"mean", "std", "min", "max", "p00135", "p50", "p99865"} <= set(
            entry["monte_carlo"])
        assert key in record["units"]
    assert any("sobol" in entry for entry in record["results"].values())
    assert 0 <= record["yield"] <= 1


@pytest.mark.parametrize("spec", TOLERANCED, ids=lambda p: p.stem)
def test_every_kind_prints_a_table(cli, spec):
    run = cli("tolerance", spec, "--samples", "4096")
    verdict = cli("tolerance", spec, "--samples", "4096", "--format", "json")
    assert run.code == verdict.code == study_status(json.loads(verdict.out)), run.err
    assert "worst case" in run.out and "Monte Carlo" in run.out


def test_methods_not_run_are_left_out(cli):
    run = cli("tolerance", TOLERANCED[-1], "--method", "rss", "--format", "json")
    record = json.loads(run.out)
    entry = next(iter(record["results"].values()))
    assert "rss" in entry and "worst_case" not in entry and "monte_carlo" not in entry
    assert "samples" not in record and "yield" not in record and "cpk" not in record


def test_result_option_leads_the_table_and_narrows_monte_carlo(cli):
    run = cli("tolerance", ROOT / "specs/tolerances/thrust-bearing.yaml", "--result",
              "cage_speed", "-n", "4096", "-f", "json")
    record = json.loads(run.out)
    assert "monte_carlo" in record["results"]["cage_speed"]
    assert "monte_carlo" not in record["results"]["ball_speed"]
    assert "worst_case" in record["results"]["ball_speed"]


@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_plot_is_a_valid_image(cli, tmp_path, suffix):
    path = tmp_path / f"hist{suffix}"
    run = cli("tolerance", ROOT / "specs/tolerances/thrust-bearing.yaml", "-n", "8192",
              "--plot", path)
    assert run.code == 0, run.err  # the example stays within its slip limit
    data = path.read_bytes()
    assert len(data) > 5000
    if suffix == ".png":
        assert data.startswith(b"\x89PNG\r\n\x1a\n")
        from matplotlib.image import imread

        assert imread(path).shape[0] > 300
    else:
        assert b"<svg" in data[:2000]


def test_random_sampler_and_seed_are_recorded(cli):
    run = cli("tolerance", TOLERANCED[0], "-n", "5000", "--sampler", "random", "--seed", "3",
              "-f", "json", "--method", "monte-carlo")
    record = json.loads(run.out)
    assert (record["sampler"], record["seed"], record["samples"]) == ("random", 3, 5000)


BAD = [
    ("contact_angle: 30 deg ± -0.25 deg", "tolerance must not be negative"),
    ("contact_angle: 30 deg ± 0.25 mm", "'mm' is not a unit of angle"),
    ("contact_angle: {nominal: 30 deg, tolerance: 1 deg, distribution: gauss}",
     "unknown distribution 'gauss'"),
    ("contact_angle: {nominal: 30 deg, plus: 1 deg}", "needs tolerance, or both plus and minus"),
    ("pitch_radius: 26 mm ± 30 mm", "must be greater than zero, got the band's low end"),
    ("ball_count: 12 ± 1", "must be a whole number of balls"),
]


@pytest.mark.parametrize(("line", "fragment"), BAD, ids=[f"bad{i}" for i in range(len(BAD))])
def test_bad_tolerance_input_is_one_line_and_exit_2(cli, spec_file, line, fragment):
    key = line.split(":")[0]
    text = "\n".join(row for row in TB.splitlines() if not row.startswith(key + ":"))
    run = cli("tolerance", spec_file(text + "\n" + line + "\n"))
    assert run.code == 2
    assert run.err.count("\n") == 1 and fragment in run.err, run.err


@pytest.mark.parametrize(("args", "fragment"), [
    (["--method", "exact"], "unknown method 'exact'"),
    (["--sampler", "halton"], "unknown sampler 'halton'"),
    (["--result", "speed"], "'--result' / '-r': 'speed' is not a result"),
    (["--plot", "x.pdf"], "give a .png or .svg"),
    (["--plot", "x.png", "--method", "rss"], "add monte-carlo"),
])
def test_bad_options_are_one_line_and_exit_2(cli, spec_file, args, fragment):
    run = cli("tolerance", spec_file(TB), *args)
    assert run.code == 2 and fragment in run.err and run.err.count("\n") == 1, run.err


def test_no_tolerance_and_sobol_with_one_input_are_clear_errors(cli):
    run = cli("tolerance", ROOT / "specs" / "thrust-bearing.yaml")
    assert run.code == 2 and "no tolerances" in run.err
    one = ROOT / "specs" / "tolerances" / "bevel-gears.yaml"
    assert cli("tolerance", one, "--sobol", "-n", "2048").code == 1  # the apex limit


def test_limit_exceeded_at_worst_case_exits_1(cli, spec_file):
    run = cli("tolerance", spec_file(TB), "-n", "4096")
    assert run.code == 1 and "FAIL" in run.out
    # in engineering terms, as solve says it: the quantity against its limit
    assert re.search(r"at worst case, spin-to-roll ratio [\d.]+ > max 0\.004 \(margin −", run.out)


def test_the_worst_case_verdict_is_the_life_at_the_worst_design():
    """The verdict's life is the life where the margin is least: the worst case's own
    minimum of the life, found by its own search, and its requirement the spec's."""
    from bearingcalc.evaluation import load_one_spec
    from bearingcalc.studies import run_study

    kind, spec, _ = load_one_spec(ROOT / "specs" / "tolerances" / "ball-bearing.yaml")
    record = run_study(kind, spec, "spec", methods=["worst-case"]).record
    weakest = record["worst_case_verdicts"][0]
    results = record["results"]
    assert weakest["key"] == "life_margin" and weakest["unit"] == "s"
    assert weakest["limit"] == pytest.approx(2000 * 3600.0, rel=1e-12)
    assert weakest["value"] == pytest.approx(
        results["modified_rating_life"]["worst_case"]["min"], rel=1e-9)
    assert weakest["value"] / weakest["limit"] - 1 == pytest.approx(
        results["life_margin"]["worst_case"]["min"], rel=1e-12)
    margins = [v["margin"] for v in record["worst_case_verdicts"]]
    assert margins == sorted(margins)


def test_sobol_gives_no_numbers_where_designs_are_impossible_or_results_constant(spec_file):
    study = study_of(spec_file, TB.replace("30 deg ± 0.25 deg", "44 deg ± 3 deg"))
    indices = sobol_indices(study, 1 << 12, keys=["spin_to_roll", "shaft_speed"])
    assert indices["spin_to_roll"] == "impossible designs in the sample"
    feasible = sobol_indices(study_of(spec_file, TB), 1 << 12, keys=["spin_to_roll", "shaft_speed"])
    assert feasible["shaft_speed"] == "does not vary with the tolerances"
    assert abs(sum(feasible["spin_to_roll"]["first_order"].values()) - 1) < 0.05


def test_a_study_where_every_sample_is_impossible_still_reports_and_plots(cli, spec_file,
                                                                          tmp_path):
    path = tmp_path / "hist.png"
    # A nominal design that solve refuses is refused by tolerance too.
    run = cli("tolerance", spec_file(TB.replace("30 deg ± 0.25 deg", "50 deg ± 1 deg")),
              "-n", "2048", "--plot", path)
    assert run.code == 2 and "contact_angle: pure rolling needs" in run.err, run.err
    assert not path.exists()
    # A possible nominal whose band is impossible beyond it (θ >= 45°) almost everywhere.
    band = "{nominal: 44.999 deg, plus: 5 deg, minus: 0 deg, distribution: uniform}"
    run = cli("tolerance", spec_file(TB.replace("30 deg ± 0.25 deg", band)),
              "-n", "2048", "--plot", path)
    assert run.code == 1, run.err
    assert "2048 samples" in run.out and "impossible designs" in run.out
    assert "FAIL" in run.out
    assert path.read_bytes().startswith(b"\x89PNG")


@pytest.mark.parametrize(("old", "new", "field", "end"), [
    ("spiral_angle: 35 deg", "spiral_angle: 0.5 deg ± 1 deg", "spiral_angle", "low"),
    ("spiral_angle: 35 deg", "spiral_angle: 49.5 deg ± 1 deg", "spiral_angle", "high"),
])
def test_a_band_that_leaves_what_the_spec_takes_is_refused(cli, spec_file, old, new, field,
                                                           end):
    """The model's rules hold at both ends of every band, as at every corner of a sweep:
    a spiral angle studied at −0.5° would flip the hand unseen."""
    text = (ROOT / "specs" / "bevel-gears-spiral.yaml").read_text().replace(old, new)
    assert new in text
    run = cli("tolerance", spec_file(text), "-n", "1000")
    assert run.code == 2 and run.err.count("\n") == 1 and run.out == "", run.err
    assert f": {field}: the {end} end of its tolerance band" in run.err, run.err
    line = next(i for i, row in enumerate(text.splitlines(), 1) if row.startswith(new))
    assert f".yaml:{line}: " in run.err, run.err


def test_a_one_sided_limit_gets_its_cpl(cli):
    """A life held above its requirement: Cpl = (μ − L)/3σ of the life itself, the same
    as the margin's μ/3σ (the margin is the life over L, less 1)."""
    run = cli("tolerance", ROOT / "specs" / "tolerances" / "ball-bearing.yaml", "-n", "20000",
              "--format", "json")
    record = json.loads(run.out)
    life = record["results"]["modified_rating_life"]["monte_carlo"]
    required = 2000 * 3600.0  # the spec's min_rating_life
    expected = (life["mean"] - required) / (3 * life["std"])
    entry = record["capability"]["life_margin"]
    assert entry["index"] == "Cpl" and entry["of"] == "modified rating life"
    assert entry["value"] == pytest.approx(expected, rel=1e-9)
    table = cli("tolerance", ROOT / "specs" / "tolerances" / "ball-bearing.yaml", "-n", "20000")
    assert f"Cpl {expected:.3g} (modified rating life)" in table.out
    out = 1 - record["yield"]
    assert f"{100 * out:.3g} % out of spec" in table.out  # above 0.1 %: in %


def test_a_temperature_stays_in_the_unit_it_was_written_in(cli, spec_file):
    text = ((ROOT / "specs" / "rolling-bearing-spherical-roller.yaml").read_text()
            .replace("temperature: 70 degC", "temperature: 70 degC ± 5 degC"))
    assert "70 degC ± 5 degC" in text
    run = cli("tolerance", spec_file(text), "-n", "2000")
    assert run.code in (0, 1), run.err
    row = next(line for line in run.out.splitlines() if "lubrication.temperature" in line)
    cells = [cell.strip() for cell in row.split("│") if cell.strip()]
    assert cells[1:5] == ["70", "65", "75", "degC"], cells


def test_every_input_stays_in_the_unit_it_was_written_in(cli, spec_file):
    """0.5 in ± 0.0002 in is shown in inches, not as 12.7 mm; rpm as rpm."""
    text = TB.replace("12.7 mm ± 0.005 mm", "0.5 in ± 0.0002 in").replace(
        "1500 rpm", "25 rev/s ± 0.5 rev/s")
    run = cli("tolerance", spec_file(text), "-n", "1024", "--method", "worst-case")
    assert run.code in (0, 1), run.err
    row = next(line for line in run.out.splitlines() if "ball_diameter" in line)
    cells = [cell.strip() for cell in row.split("│") if cell.strip()]
    assert [float(c) for c in cells[1:4]] == pytest.approx([0.5, 0.4998, 0.5002], rel=1e-12)
    assert cells[4] == "in"
    row = next(line for line in run.out.splitlines() if "pitch_radius" in line)
    assert "mm" in row and "26" in row
    row = next(line for line in run.out.splitlines() if "shaft_speed" in line)
    cells = [cell.strip() for cell in row.split("│") if cell.strip()]
    assert [float(c) for c in cells[1:4]] == pytest.approx([25, 24.5, 25.5], rel=1e-12)
    assert cells[4] == "rev/s"


def test_rss_says_when_the_band_crosses_a_switch(cli, spec_file):
    """A tapered pair at Fa/Fr = 0.28 whose axial load band (1–4 kN) crosses e = 0.37:
    X and Y switch within the band, which RSS, linear at the centre, cannot see."""
    text = (ROOT / "specs" / "rolling-bearing.yaml").read_text().replace(
        "axial_load: 2.5 kN ", "axial_load: 2.5 kN ± 1.5 kN ", 1)
    assert "2.5 kN ± 1.5 kN" in text
    record = json.loads(cli("tolerance", spec_file(text), "-n", "2000", "--format", "json").out)
    assert record["results"]["modified_rating_life"]["rss"]["switches"] == [
        "radial_factor", "axial_factor"]
    assert any(w.startswith("RSS linearises at the centre, but the design switches")
               for w in record["warnings"])


def test_the_note_on_normal_tails_gives_each_band_in_sigma(cli, spec_file):
    """A band of ±1.5σ leaves erfc(1.5/√2) = 13.4 % of the draws outside it."""
    text = TB.replace("30 deg ± 0.25 deg", "{nominal: 30 deg, tolerance: 0.25 deg, "
                      "sigma_level: 1.5}")
    run = cli("tolerance", spec_file(text), "-n", "1024")
    assert run.code in (0, 1), run.err
    said = " ".join(run.out.split())
    assert f"contact_angle ±1.5σ: {100 * math.erfc(1.5 / math.sqrt(2)):.3g} %" in said
    assert "ball_diameter, pitch_radius ±3σ: 0.27 %" in said
