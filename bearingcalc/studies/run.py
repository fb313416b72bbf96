"""Running a tolerance study: the chosen methods, the record they fill (the JSON
contract) and its verdict against the spec's limits."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from bearingcalc.kinds import KINDS, Kind
from bearingcalc.models.base import SpecModel
from bearingcalc.studies.monte_carlo import monte_carlo, one_sided_capability, smallest_cpk
from bearingcalc.studies.rss import rss
from bearingcalc.studies.sampling import SAMPLERS, SOBOL_MAX_SAMPLES
from bearingcalc.studies.sensitivity import sobol_indices
from bearingcalc.studies.study import Study, StudyError
from bearingcalc.studies.worst_case import worst_case
from bearingcalc.units import to_display
from bearingcalc.verdicts import judge

METHODS = ("worst-case", "rss", "monte-carlo")


@dataclass
class StudyReport:
    """Everything a tolerance run found: the contract's JSON object and the histograms."""

    record: dict[str, Any]
    histograms: dict[str, tuple[NDArray, NDArray]]
    governing: list[str]
    limits: dict[str, float]
    margins: tuple[str, ...]
    #: result key -> (unit, factor from SI) where the kind's tables use their own unit
    display: dict[str, tuple[str, float]] = field(default_factory=dict)

    @property
    def plotted(self) -> str | None:
        """The result a plot shows by default: the margin that comes nearest its limit
        (the one that fails, if any) by worst case or Monte Carlo, else the first
        governing result."""
        judged = [key for key in self.margins if key in self.histograms]
        if judged:
            weakest = weakest_margin(self.record, judged)
            # the quantity it judges says the same with its limit in its own unit (a life
            # in hours against the required life), where it was sampled
            judges = KINDS[self.record["kind"]].judged.get(weakest)
            quantity = getattr(judges, "quantity", None)
            return quantity if isinstance(quantity, str) and quantity in self.histograms \
                else weakest
        return self.governing[0] if self.governing else None

    @property
    def within_limits(self) -> bool | None:
        """Whether every margin stays >= 0: at worst case if run, else in every sample."""
        results = self.record["results"]
        if self.record.get("impossible_in_box") or self.record.get("infeasible_samples"):
            return False  # a box holding impossible designs never passes
        if not self.margins:
            return None
        worst = [results[m].get("worst_case", {}).get("min") for m in self.margins]
        if all(w is not None for w in worst):
            return all(w >= 0 for w in worst)  # type: ignore[operator]
        if "yield" in self.record:
            return bool(self.record["yield"] == 1.0)  # Monte Carlo alone: every sample
        return None


def weakest_margin(record: dict[str, Any], margins: Sequence[str]) -> str:
    """Of ``margins``, the one that comes nearest its limit (the one that fails, if any)
    by worst case or Monte Carlo, whichever reaches lower."""
    results = record["results"]

    def lowest(key: str) -> float:
        entry = results.get(key, {})
        found = [(entry.get("worst_case") or {}).get("min"),
                 (entry.get("monte_carlo") or {}).get("min")]
        values = [value for value in found if value is not None]
        return min(values) if values else float("inf")

    return min(margins, key=lowest)


def run_study(kind: Kind, spec: SpecModel, source: str, *, methods: Sequence[str],
              samples: int = 100_000, seed: int = 0, sampler: str = "sobol",
              sobol: bool = False, results: Sequence[str] = (), threads: int = 2,
              progress: Callable[[int], None] | None = None) -> StudyReport:
    """Run the chosen methods and assemble the report (SI units throughout).

    ``results`` narrows Monte Carlo and Sobol to those result keys (and names the
    governing results); worst case and RSS always cover every result.
    """
    if not methods:
        raise StudyError(f"names no method; use one or more of {', '.join(METHODS)}",
                         "--method")
    unknown = [m for m in methods if m not in METHODS]
    if unknown:
        raise StudyError(f"unknown method {unknown[0]!r}; use {', '.join(METHODS)}",
                         "--method")
    if sampler not in SAMPLERS:
        raise StudyError(f"unknown sampler {sampler!r}; use {' or '.join(SAMPLERS)}",
                         "--sampler")
    if sampler == "sobol" and "monte-carlo" in methods and samples > SOBOL_MAX_SAMPLES:
        raise StudyError(f"{samples} is more than the {SOBOL_MAX_SAMPLES} distinct Sobol' "
                         "points of 30 bits; use --sampler random for more", "--samples")
    study = Study(kind, spec)
    missing = [key for key in results if key not in study.keys]
    if missing:
        raise StudyError(f"{missing[0]!r} is not a result of this {kind.name} spec; "
                         f"choose from {', '.join(study.keys)}", "--result")
    governing = list(results) or [key for key in kind.governing if key in study.keys]
    focus = list(results) or study.keys
    record: dict[str, Any] = {
        "spec": source, "kind": kind.name, "name": getattr(spec, "name", None),
        **spec.catalogue_sources(),  # type: ignore[attr-defined]
        "inputs": study.input_summary(),
        "results": {key: {"nominal": value} for key, value in study.nominal.items()},
        "units": {**{key: kind.results[key][0] for key in study.keys},
                  **{item.name: item.tolerance.unit for item in study.inputs}},
        "warnings": spec.study_notes([item.name for item in study.inputs]),
    }
    if "worst-case" in methods:
        for key, entry in worst_case(study).items():
            record["results"][key]["worst_case"] = entry
        record["worst_case_verdicts"] = worst_case_verdicts(study, record["results"])
    else:
        # Every method must know when the box crosses a validity edge, not only the
        # worst case: RSS at the centre and a lucky sample would otherwise pass it.
        study.scan_box()
    if study.box_impossible is not None:
        box = study.box_impossible
        record["impossible_in_box"] = box
        at = ", ".join("{} = {:.6g} {}".format(name, *to_display(value, record["units"][name]))
                       for name, value in box["inputs"].items())
        covers = ("worst case covers only the possible part, and " if "worst-case" in methods
                  else "")
        record["warnings"].append(
            f"{100 * box['fraction']:.3g} % of the worst-case search of the tolerance box "
            f"are impossible designs, e.g. at {at} ({box['reason']}); {covers}the study "
            "fails")
    if "rss" in methods:
        switches: list[str] = []
        for key, entry in rss(study).items():
            record["results"][key]["rss"] = entry
            switches = switches or entry.get("switches", [])
        if switches:
            trusted = ("the worst case" if "worst-case" in methods else "") + (
                " or Monte Carlo" if "monte-carlo" in methods else "")
            record["warnings"].append(
                f"RSS linearises at the centre, but the design switches within the "
                f"tolerance band ({', '.join(switches)} change"
                f"{'s' if len(switches) == 1 else ''} there): trust "
                f"{trusted.removeprefix(' or ') or 'worst case or Monte Carlo'} instead")
    histograms: dict[str, tuple[NDArray, NDArray]] = {}
    if "monte-carlo" in methods:
        mc = monte_carlo(study, samples, seed, sampler, threads=threads,
                         keys=list(dict.fromkeys([*focus, *study.margins])),
                         progress=progress)
        for key, stats in mc.stats.items():
            record["results"][key]["monte_carlo"] = stats
        record.update({"samples": samples, "seed": seed, "sampler": sampler,
                       "yield": mc.yield_fraction, "ppm_out": mc.ppm_out,
                       "cpk": smallest_cpk(study, mc), "infeasible_samples": mc.infeasible,
                       "capability": one_sided_capability(study, mc)})
        if mc.infeasible:
            record["warnings"].append(f"{mc.infeasible} of {samples} samples are impossible "
                                      "designs; they count as out of spec")
        histograms = mc.histograms
    if sobol:
        for key, entry in sobol_indices(study, samples, seed, focus).items():
            if isinstance(entry, str):
                record["warnings"].append(f"{key}: no Sobol indices, {entry}")
            else:
                record["results"][key]["sobol"] = entry
    record = _finite(record)
    if not results and study.margins:  # the margin nearest its limit leads the tables
        weakest = weakest_margin(record, study.margins)
        governing = [weakest, *(key for key in governing if key != weakest)]
    return StudyReport(record, histograms, governing, study.limit_values,
                       tuple(study.margins), dict(kind.display))


def _finite(value: Any) -> Any:
    """The record with every non-finite float replaced by None (JSON has no NaN)."""
    if isinstance(value, dict):
        return {key: _finite(item) for key, item in value.items()}
    if isinstance(value, list):
        return [_finite(item) for item in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def worst_case_verdicts(study: Study, results: dict[str, Any]) -> list[dict[str, Any]]:
    """Each margin judged at the design where the worst case puts its minimum, in
    engineering terms (the life and its requirement, not the margin), the weakest
    first: the fields of :class:`~bearingcalc.verdicts.Verdict`, SI."""
    worst = {m: results[m]["worst_case"] for m in study.margins
             if (results[m].get("worst_case") or {}).get("min_inputs") is not None}
    if not worst:
        return []
    rows = np.array([[entry["min_inputs"][item.name] for item in study.inputs]
                     for entry in worst.values()])
    values, _ = study.evaluate(rows)
    verdicts = []
    for i, (margin, entry) in enumerate(worst.items()):
        at = {key: float(np.asarray(column).reshape(-1)[i]) for key, column in values.items()}
        verdicts += judge(study.kind.judged, study.kind.results, at, {margin: entry["min"]})
    return [asdict(verdict) for verdict in sorted(verdicts, key=lambda v: v.margin)]
