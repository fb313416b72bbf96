"""The calculation report of a spec file: each document solved as ``solve`` solves it,
its inputs read back as written and in SI, the plots that fit its kind made from the
same solver, all written by :func:`bearingcalc.reports.html.report_html`."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from bearingcalc import __version__
from bearingcalc.errors import SpecError
from bearingcalc.evaluation import evaluate_document, load_selected, parse_document
from bearingcalc.kinds import KINDS
from bearingcalc.models.base import field_parser
from bearingcalc.models.field_path import FieldPathError, resolve_field
from bearingcalc.models.quantities import Measured
from bearingcalc.models.yaml_loader import read_spec_text
from bearingcalc.reports.html import report_html, svg_of

#: The life-against-load curve runs from this fraction of the operating load to this
#: multiple of it.
LOAD_SPAN = (0.25, 4.0)


def report_of(path: str | Path) -> str:
    """The HTML report of every document of the spec file at ``path``; SpecError where
    a document cannot be read or solved (as ``solve`` would refuse it)."""
    documents = load_selected(path)
    text = read_spec_text(str(path).rpartition("#")[0] if not Path(path).exists()
                          else path)
    evaluations, inputs, plots = [], [], []
    for document in documents:
        evaluation = evaluate_document(document)
        kind, spec = parse_document(document)
        evaluations.append(evaluation)
        inputs.append(list(_inputs(document.data, spec)))
        plots.append(_plots(kind, spec, evaluation))
    return report_html(evaluations, KINDS, text, str(path), __version__, inputs, plots)


def _leaves(data: Any, prefix: str = "") -> Iterator[tuple[str, Any]]:
    if isinstance(data, dict):
        if {"nominal"} <= set(data):  # a toleranced value, as one input
            yield prefix, data
            return
        for key, value in data.items():
            yield from _leaves(value, f"{prefix}.{key}" if prefix else str(key))
    elif isinstance(data, list):
        for i, value in enumerate(data, 1):
            yield from _leaves(value, f"{prefix}.{i}")
    else:
        yield prefix, data


def _inputs(data: Any, spec: Any) -> Iterator[tuple[str, str, str]]:
    """(field, as written, in SI) of every input the spec gives."""
    for name, written in _leaves(data):
        if name in ("kind", "name"):
            continue
        shown = written if isinstance(written, str) else (
            "{" + ", ".join(f"{k}: {v}" for k, v in written.items()) + "}"
            if isinstance(written, dict) else str(written))
        try:
            found = resolve_field(spec, name)
        except FieldPathError:
            yield name, shown, ""
            continue
        value = found.value
        if isinstance(value, Measured):  # a toleranced input: its nominal value
            value = float(value)
        parsed = field_parser(found.info) if found.info is not None else None
        unit = "" if parsed is None or parsed[2] == "1" else f" {parsed[2]}"
        if isinstance(value, bool):
            si = "true" if value else "false"
        elif isinstance(value, float):
            si = f"{value:.10g}{unit}"  # ten digits: the float's own, not its last bits
        else:
            si = str(value)
        yield name, shown, si


def _plots(kind: Any, spec: Any, evaluation: Any) -> list[tuple[str, str]]:
    """The plots that fit the kind: a bearing's life against its load, a drive's
    bearings' lives against the required life, a duty cycle's damage per bin."""
    plots = []
    bins = _table(evaluation, "bin")
    shares = bins is not None and "damage_share" in bins.columns
    if shares:
        plots.append(_damage_plot(evaluation, bins))
    elif kind.name in ("rolling-bearing", "ball-bearing"):
        curve = _life_against_load(kind, spec, evaluation)
        if curve is not None:
            plots.append(curve)
    if kind.name == "bevel-drive":
        plots.append(_drive_lives(evaluation))
        diagram = None if shares else _shaft_loads(spec, evaluation)
        if diagram is not None:  # a duty cycle's shafts carry a load per bin, not one
            plots.append(diagram)
    return plots


def _required_life(evaluation: Any) -> float | None:
    """The required life [s], read from the life's verdict."""
    for verdict in evaluation.verdicts:
        if verdict.key == "life_margin":
            return float(verdict.limit)
    return None


def _life_against_load(kind: Any, spec: Any, evaluation: Any) -> tuple[str, str] | None:
    from bearingcalc.sweeps import parse_axis, run_sweep

    load = float(spec.radial_load)  # a toleranced load's nominal value
    life = evaluation.results.get("modified_rating_life")
    if not load > 0 or life is None:
        return None
    low, high = (factor * load for factor in LOAD_SPAN)
    try:
        solved = run_sweep(kind, spec, evaluation.source,
                           [parse_axis(f"radial_load={low!r}N:{high!r}N:60", spec)])
    except (SpecError, ValueError):
        return None
    loads = solved.inputs["radial_load"] / 1e3
    lives = solved.results["modified_rating_life"] / 3600.0
    required = _required_life(evaluation)

    def draw(axes: Any) -> None:
        axes.plot(loads, lives, color="#4c72b0", label="modified rating life")
        axes.plot([load / 1e3], [life / 3600.0], "o", color="#c44e52",
                  label="the operating point")
        if required is not None:
            axes.axhline(required / 3600.0, color="#c44e52", linestyle=":",
                         label="required life")
        from matplotlib.ticker import NullFormatter, ScalarFormatter

        axes.set_xscale("log")
        axes.set_yscale("log")
        axes.xaxis.set_major_formatter(ScalarFormatter())  # 2, 5, 10 kN: plain numbers
        axes.xaxis.set_minor_formatter(NullFormatter())
        axes.set_xticks([tick for tick in (1, 2, 5, 10, 20, 50, 100, 200, 500, 1000)
                         if low / 1e3 <= tick <= high / 1e3] or axes.get_xticks())
        axes.set_xlabel("radial load [kN]")
        axes.set_ylabel("modified rating life [h]")
        axes.grid(alpha=0.3, which="both")
        axes.legend(fontsize="small")

    return ("The modified rating life against the radial load, the other inputs as given "
            "(ISO 281, the same solver as the results above).", svg_of(draw))


def _table(evaluation: Any, axis: str) -> Any:
    """The first table of the results along ``axis``, or None."""
    return next((table for table in evaluation.tables if table.axis == axis), None)


def _drive_lives(evaluation: Any) -> tuple[str, str]:
    results = evaluation.results
    bearings = [(row, key) for table in evaluation.tables if table.axis == "member"
                for row, key in zip(table.rows, table.column("modified_rating_life"),
                                    strict=True) if key is not None]
    keys = [key for _, key in bearings] + ["system_modified_rating_life"]
    names = [row.replace("_", " ") for row, _ in bearings] + ["system"]
    lives = np.array([np.inf if results[key] is None else results[key] / 3600.0
                      for key in keys])
    required = _required_life(evaluation)

    def draw(axes: Any) -> None:
        bars = axes.barh(names, np.where(np.isfinite(lives), lives, 0.0), color="#4c72b0")
        # the bars start at the axis' edge, not at zero (a log axis): the numbers say it
        axes.bar_label(bars, labels=[f"{life:,.0f} h".replace(",", "\u202f")
                                     if np.isfinite(life) else "unbounded" for life in lives],
                       padding=3, fontsize="small")
        axes.margins(x=0.25)
        if required is not None:
            axes.axvline(required / 3600.0, color="#c44e52", linestyle=":",
                         label="required life (of the system)")
            axes.legend(fontsize="small")
        axes.set_xscale("log")
        axes.set_xlabel("modified rating life [h]")
        axes.grid(alpha=0.3, axis="x", which="both")

    return ("Each bearing's modified rating life and the system's, against the required "
            "life.", svg_of(draw))


def _damage_plot(evaluation: Any, table: Any) -> tuple[str, str]:
    results = evaluation.results
    shares = table.column("damage_share")
    bins = [evaluation.row_names.get(row, str(position + 1))
            for row, position in zip(table.rows, table.positions, strict=True)]
    damage = [100.0 * (results[key] or 0.0) for key in shares]
    times = [100.0 * (results.get(key) or 0.0) for key in table.column("time_share")]

    def draw(axes: Any) -> None:
        positions = np.arange(len(shares))
        axes.bar(positions - 0.2, times, width=0.4, color="#8da0cb", label="time share")
        axes.bar(positions + 0.2, damage, width=0.4, color="#c44e52", label="damage share")
        axes.set_xticks(positions, [str(name) for name in bins])
        axes.set_ylabel("share [%]")
        axes.set_xlabel("bin of the duty cycle")
        axes.legend(fontsize="small")
        axes.grid(alpha=0.3, axis="y")

    return ("Each bin's share of the time and of the fatigue damage (Palmgren–Miner).",
            svg_of(draw))


def _shaft_loads(spec: Any, evaluation: Any) -> tuple[str, str] | None:
    """Each shaft's bending moment along its axis, with its bearings and its gear."""
    from bearingcalc.core.bevel_drive import mean_pitch_point, shaft_bending_moments

    results = evaluation.results
    shafts = spec.solver_inputs()["shafts"]
    # the bearings' tables come a shaft each, in the shafts' order
    tables = iter(table for table in evaluation.tables if table.axis == "member")
    drawn = []
    for shaft, gear in (("pinion", "a"), ("gear", "b")):
        if shaft not in shafts:
            continue
        loads = [results[key] for key in next(tables).column("radial_load")]
        positions = tuple(float(bearing["position"]) for bearing in shafts[shaft])
        angle = results[f"gear_{gear}_pitch_angle"]
        mesh, radius = (float(v) for v in mean_pitch_point(results["mean_cone_distance"],
                                                             angle))
        ends = [*positions, mesh]
        x = np.linspace(min(ends), max(ends), 801)
        x = np.unique(np.concatenate([x, ends]))
        moment_y, moment_z = shaft_bending_moments(
            x, positions, mesh, radius, results["tangential_force"],
            results[f"gear_{gear}_radial_force"], results[f"gear_{gear}_axial_force"])
        drawn.append((shaft, x, np.hypot(moment_y, moment_z), positions, mesh, loads))
    if not drawn:
        return None

    def draw(panels: list[Any]) -> None:
        for axes, (shaft, x, moment, positions, mesh, loads) in zip(panels, drawn,
                                                                    strict=True):
            axes.plot(x * 1e3, moment, color="#4c72b0")
            axes.plot([mesh * 1e3], [0.0], "v", color="#c44e52", markersize=9, linestyle="none",
                      label=f"mean pitch point of the {shaft}")
            axes.plot([p * 1e3 for p in positions], [0.0, 0.0], "^", color="#333333",
                      markersize=9, linestyle="none", label="bearing, with its radial load")
            for i, (at, load) in enumerate(zip(positions, loads, strict=True), 1):
                axes.annotate(f"bearing {i}: {load / 1e3:.3g} kN", (at * 1e3, 0.0),
                              textcoords="offset points", xytext=(0, -17), ha="center",
                              fontsize="small")
            axes.set_title(f"{shaft} shaft", fontsize="medium", loc="left")
            axes.set_ylabel("bending moment [N·m]")
            axes.set_ylim(-0.3 * moment.max(), 1.15 * moment.max())
            axes.margins(x=0.15)
            axes.grid(alpha=0.3)
            axes.legend(fontsize="small", loc="upper right")
        panels[-1].set_xlabel("position along the shaft from the pitch-cone apex [mm]")

    return ("Each shaft's bending moment (the resultant of its two planes) along its axis; "
            "its bearings with their radial loads and the gear's mean pitch point. Rigid "
            "shaft on two simple supports, as the bearing loads above.",
            svg_of(draw, panels=len(drawn)))
