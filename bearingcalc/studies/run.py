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
from bearingcalc.result_keys import ResultTable
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
    #: the tables of the results along axes (a drive's bearings, a cycle's bins)
    tables: tuple[ResultTable, ...] = ()
    #: the catalogue row of each bearing taken from one (also in the record): result-style
    #: key -> designation, maker and source
    catalogue_sources: dict[str, str] = field(default_factory=dict)

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
            quantity = None if judges is None else judges.key(self.histograms)
            return quantity if quantity is not None else weakest
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


def run_study(  # noqa: PLR0913  the tolerance command's options, keyword-only, one per flag
        kind: Kind, spec: SpecModel, source: str, *, methods: Sequence[str],
        samples: int = 100_000, seed: int = 0, sampler: str = "sobol",
        sobol: bool = False, results: Sequence[str] = (), threads: int = 2,
        progress: Callable[[int], None] | None = None) -> StudyReport:
    """Run the chosen methods and assemble the report (SI units throughout).

    ``results`` narrows Monte Carlo and Sobol to those result keys (and names the
    governing results); worst case and RSS always cover every result.
    """
    _check_options(methods, sampler, samples)
    study = Study(kind, spec)
    missing = [key for key in results if key not in study.keys]
    if missing:
        raise StudyError(f"{missing[0]!r} is not a result of this {kind.name} spec; "
                         f"choose from {', '.join(study.keys)}", "--result")
    governing = list(results) or kind.governing_of(study.keys)
    focus = list(results) or study.keys
    record = _first_record(kind, spec, source, study)
    by_method: dict[str, dict[str, Any]] = {}  # method -> result key -> its entry
    if "worst-case" in methods:
        by_method["worst_case"] = worst_case(study)
        record["worst_case_verdicts"] = worst_case_verdicts(
            study, {m: {"worst_case": by_method["worst_case"].get(m)} for m in study.margins})
    else:
        # Every method must know when the box crosses a validity edge, not only the
        # worst case: RSS at the centre and a lucky sample would otherwise pass it.
        study.scan_box()
    if study.box_impossible is not None:
        record["impossible_in_box"] = study.box_impossible
        record["warnings"].append(_impossible_box_warning(study.box_impossible,
                                                          record["units"], methods))
    if "rss" in methods:
        by_method["rss"] = rss(study)
        record["warnings"] += _rss_switches_warning(by_method["rss"], methods)
    histograms: dict[str, tuple[NDArray, NDArray]] = {}
    if "monte-carlo" in methods:
        mc = monte_carlo(study, samples, seed, sampler, threads=threads,
                         keys=list(dict.fromkeys([*focus, *study.margins])),
                         progress=progress)
        by_method["monte_carlo"] = mc.stats
        record.update({"samples": samples, "seed": seed, "sampler": sampler,
                       "yield": mc.yield_fraction, "ppm_out": mc.ppm_out,
                       "cpk": smallest_cpk(study, mc), "infeasible_samples": mc.infeasible,
                       "capability": one_sided_capability(study, mc)})
        if mc.infeasible:
            record["warnings"].append(f"{mc.infeasible} of {samples} samples are impossible "
                                      "designs; they count as out of spec")
        histograms = mc.histograms
    if sobol:
        indices = sobol_indices(study, samples, seed, focus)
        by_method["sobol"] = {k: e for k, e in indices.items() if not isinstance(e, str)}
        record["warnings"] += [f"{key}: no Sobol indices, {entry}"
                               for key, entry in indices.items() if isinstance(entry, str)]
    # each result's entry: its nominal value, then the methods in the order they ran
    record["results"] = {key: {**entry, **{method: found[key] for method, found
                                           in by_method.items() if key in found}}
                         for key, entry in record["results"].items()}
    record = _finite(record)
    if not results and study.margins:  # the margin nearest its limit leads the tables
        weakest = weakest_margin(record, study.margins)
        governing = [weakest, *(key for key in governing if key != weakest)]
    return StudyReport(record, histograms, governing, study.limit_values,
                       tuple(study.margins), dict(kind.display), study.layout({}).tables,
                       spec.catalogue_sources())  # type: ignore[attr-defined]


def _check_options(methods: Sequence[str], sampler: str, samples: int) -> None:
    """Refuse an empty or unknown method, an unknown sampler, and more Sobol' samples
    than its 30-bit sequence has distinct points."""
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


def _first_record(kind: Kind, spec: SpecModel, source: str, study: Study) -> dict[str, Any]:
    """The record before any method runs: the spec, its inputs, the nominal results,
    every unit (SI) and the spec's own notes on the study."""
    return {
        "spec": source, "kind": kind.name, "name": getattr(spec, "name", None),
        **spec.catalogue_sources(),  # type: ignore[attr-defined]
        "inputs": study.input_summary(),
        "results": {key: {"nominal": value} for key, value in study.nominal.items()},
        "units": {**{key: study.names[key][0] for key in study.keys},
                  **{item.name: item.tolerance.unit for item in study.inputs}},
        "warnings": spec.study_notes([item.name for item in study.inputs]),
    }


def _impossible_box_warning(box: dict[str, Any], units: dict[str, str],
                            methods: Sequence[str]) -> str:
    """The share of the tolerance box that holds impossible designs, one of them, and
    why: the study fails."""
    at = ", ".join("{} = {:.6g} {}".format(name, *to_display(value, units[name]))
                   for name, value in box["inputs"].items())
    covers = ("worst case covers only the possible part, and " if "worst-case" in methods
              else "")
    return (f"{100 * box['fraction']:.3g} % of the worst-case search of the tolerance box "
            f"are impossible designs, e.g. at {at} ({box['reason']}); {covers}the study "
            "fails")


def _rss_switches_warning(entries: dict[str, Any], methods: Sequence[str]) -> list[str]:
    """RSS linearises at the centre: where the design switches inside the band (the first
    result that says so), the methods that sample the band are to be trusted instead."""
    switches = next((entry["switches"] for entry in entries.values()
                     if entry.get("switches")), [])
    if not switches:
        return []
    trusted = ("the worst case" if "worst-case" in methods else "") + (
        " or Monte Carlo" if "monte-carlo" in methods else "")
    return [f"RSS linearises at the centre, but the design switches within the "
            f"tolerance band ({', '.join(switches)} change"
            f"{'s' if len(switches) == 1 else ''} there): trust "
            f"{trusted.removeprefix(' or ') or 'worst case or Monte Carlo'} instead"]


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
        verdicts += judge(study.kind.judged, study.kind.results, study.layout(at),
                          {margin: entry["min"]})
    return [asdict(verdict) for verdict in sorted(verdicts, key=lambda v: v.margin)]
