"""The drawings of the calculation report, each an inline SVG with its caption; a kind
names the drawings its report makes (:attr:`bearingcalc.kinds.Kind.plots`), each a key
of :data:`DRAWINGS`. A drawing that evaluates more than the results (a shaft's bending
moment along its axis) calls the solver function its plot names, never a solver module.
"""

from __future__ import annotations

import io
import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingcalc.errors import SpecError
from bearingcalc.plots.common import pyplot, words

if TYPE_CHECKING:
    from bearingcalc.evaluation import Evaluation
    from bearingcalc.kinds import Kind, Plot
    from bearingcalc.result_keys import ResultTable

#: The life-against-load curve runs from this fraction of the operating load to this
#: multiple of it.
LOAD_SPAN = (0.25, 4.0)


def _bins(evaluation: Evaluation) -> ResultTable | None:
    """The table of a duty cycle's bins where it has each bin's damage share (none
    without a duty cycle)."""
    bins = next((table for table in evaluation.tables if table.axis == "bin"), None)
    return bins if bins is not None and "damage_share" in bins.columns else None


def _damage_shares(evaluation: Evaluation) -> list[str]:
    """The keys of a duty cycle's damage share per bin, in the bins' order (none without
    a duty cycle)."""
    bins = _bins(evaluation)
    return [] if bins is None else [key for key in bins.column("damage_share") if key]


def _required_life(evaluation: Any) -> float | None:
    """The required life [s], read from the life's verdict."""
    for verdict in evaluation.verdicts:
        if verdict.key == "life_margin":
            return float(verdict.limit)
    return None


def life_against_load(kind: Kind, spec: Any, evaluation: Evaluation, plot: Plot
                      ) -> tuple[str, str] | None:
    """A bearing's modified rating life against its radial load, the other inputs as
    given (a sweep of the same solver), with the operating point and the required life;
    none for a duty cycle, whose damage per bin is drawn instead."""
    from bearingcalc.sweeps import parse_axis, run_sweep

    if _damage_shares(evaluation):
        return None
    load = float(spec.radial_load)  # a toleranced load's nominal value
    # the life the limit judges: as mounted, the modified reference rating life
    judged = kind.judged.get("life_margin")
    key = judged.key(evaluation.results) if judged is not None else None
    key = key if key is not None else "modified_rating_life"
    life = evaluation.results.get(key)
    if not load > 0 or life is None:
        return None
    low, high = (factor * load for factor in LOAD_SPAN)
    try:
        solved = run_sweep(kind, spec, evaluation.source,
                           [parse_axis(f"radial_load={low!r}N:{high!r}N:60", spec)])
    except (SpecError, ValueError):
        return None
    loads = solved.inputs["radial_load"] / 1e3
    lives = solved.results[key] / 3600.0
    required = _required_life(evaluation)

    def draw(axes: Any) -> None:
        axes.plot(loads, lives, color="#4c72b0", label=words(key))
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
        axes.set_ylabel(f"{words(key)} [h]")
        axes.grid(alpha=0.3, which="both")
        axes.legend(fontsize="small")

    method = "ISO/TS 16281" if key != "modified_rating_life" else "ISO 281"
    return (f"The {words(key)} against the radial load, the other inputs as given "
            f"({method}, the same solver as the results above).", svg_of(draw))


def drive_lives(kind: Kind, spec: Any, evaluation: Evaluation, plot: Plot
                ) -> tuple[str, str] | None:
    """Each bearing's modified rating life and the system's, against the required life."""
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


def duty_damage(kind: Kind, spec: Any, evaluation: Evaluation, plot: Plot
                ) -> tuple[str, str] | None:
    """Each bin's share of the time and of the fatigue damage, where the design runs a
    duty cycle (else none)."""
    table = _bins(evaluation)
    if table is None:
        return None
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


def shaft_bending(kind: Kind, spec: Any, evaluation: Evaluation, plot: Plot
                  ) -> tuple[str, str] | None:
    """Each shaft's bending moment along its axis, with its bearings and its gear, by the
    solver function the plot names; none for a duty cycle, whose shafts carry a load per
    bin, not one."""
    if _damage_shares(evaluation):
        return None
    results = evaluation.results
    lines = plot.function(spec.solver_inputs()["shafts"], results)
    # the bearings' tables come a shaft each, in the shafts' order, as the lines do
    tables = [table for table in evaluation.tables if table.axis == "member"]
    drawn = [(shaft, x, moment, positions, mesh,
              [results[key] for key in table.column("radial_load")])
             for (shaft, x, moment, positions, mesh), table in zip(lines, tables, strict=True)]
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


def svg_of(draw: Callable[[Any], None], panels: int | None = None) -> str:
    """A matplotlib figure drawn by ``draw(axes)`` as inline SVG (no XML declaration);
    given a number of ``panels``, stacked, ``axes`` is their list."""
    plt = pyplot()
    count = panels or 1
    figure, grid = plt.subplots(count, 1, figsize=(7, 3.6 if count == 1 else 2.8 * count),
                                dpi=100, squeeze=False)
    axes = grid[0, 0] if panels is None else list(grid[:, 0])
    try:
        draw(axes)
        figure.tight_layout()
        buffer = io.StringIO()
        figure.savefig(buffer, format="svg")
    finally:
        plt.close(figure)
    text = buffer.getvalue()
    # The drawing alone: no XML declaration, and no metadata naming outside addresses.
    return re.sub(r"<metadata>.*?</metadata>", "", text[text.index("<svg"):], flags=re.S)


#: A drawing's name -> the function that draws it for one evaluation, or gives None where
#: it does not apply to the design (a life curve of a duty cycle).
DRAWINGS: dict[str, Callable[[Kind, Any, Evaluation, Plot], tuple[str, str] | None]] = {
    "duty-damage": duty_damage,
    "life-against-load": life_against_load,
    "bearing-lives": drive_lives,
    "shaft-bending": shaft_bending,
}


def report_plots(kind: Kind, spec: Any, evaluation: Evaluation) -> list[tuple[str, str]]:
    """(caption, SVG) of each drawing the kind names that applies to the design, in the
    kind's order."""
    drawn = (DRAWINGS[plot.name](kind, spec, evaluation, plot) for plot in kind.plots)
    return [plot for plot in drawn if plot is not None]
