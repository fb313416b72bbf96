"""No output replaces any file the run reads: a catalogue (named by the spec, by
--catalogue or by BEARINGCALC_CATALOGUE), a spec, a table shipped with the package,
however the output names it (relative, through '..', a symbolic or a hard link)."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from bearingcalc import batch, reads
from bearingcalc.catalogue.iso import TABLE
from tests.conftest import ROOT

CATALOGUE = ROOT / "specs" / "catalogues" / "example.csv"
#: The 30206 of the example catalogue on a shaft, with a tolerance for `tolerance`.
SPEC = """\
kind: rolling-bearing
name: pinion shaft
{catalogue}designation: 30206 J2/Q
maker: SKF
radial_load: 6 kN ± 0.3 kN
axial_load: 1.5 kN
speed: 1500 rpm
lubrication:
  viscosity: 68 mm^2/s
contamination_factor: 0.5
limits:
  min_rating_life: 10000 h
  min_static_safety: 2
"""
#: Each command's quick run on the spec, before --output or --plot.
COMMANDS = {
    "select": ["select", "shaft.yaml", "-f", "csv"],
    "report": ["report", "shaft.yaml"],
    "sweep": ["sweep", "shaft.yaml", "--vary", "radial_load=5kN:7kN:3", "-f", "csv"],
    "tolerance": ["tolerance", "shaft.yaml", "-m", "rss"],
    "check": ["check", "shaft.yaml", "-f", "json"],
}
#: How a run comes to read the catalogue: the spec's own field, or the run's default.
SOURCES = ["spec", "option", "environment"]
#: How the output names the catalogue.
WAYS = ["same", "dotdot", "symlink", "hardlink", "absolute"]


def fingerprint(path: Path) -> tuple[bytes, int]:
    return path.read_bytes(), path.stat().st_mtime_ns


@pytest.fixture
def shaft(tmp_path, monkeypatch):
    """A folder holding bearings.csv and shaft.yaml, as the current folder; returns a
    function writing the spec to read the catalogue from ``source`` and giving the
    extra arguments that go with it."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("BEARINGCALC_CATALOGUE", raising=False)
    shutil.copyfile(CATALOGUE, tmp_path / "bearings.csv")

    def write(source: str) -> list[str]:
        named = "catalogue: bearings.csv\n" if source == "spec" else ""
        (tmp_path / "shaft.yaml").write_text(SPEC.format(catalogue=named))
        if source == "environment":
            monkeypatch.setenv("BEARINGCALC_CATALOGUE", "bearings.csv")
        return ["--catalogue", "bearings.csv"] if source == "option" else []

    return write


def target_naming(way: str, file: Path, suffix: str = ".csv") -> str:
    """A name of ``file`` for an output, the way ``way`` says."""
    folder = file.parent
    if way == "same":
        return file.name
    if way == "absolute":
        return str(file.resolve())
    if way == "dotdot":
        (folder / "sub").mkdir(exist_ok=True)
        return f"sub/../{file.name}"
    link = folder / f"link{suffix}"
    if way == "symlink":
        link.symlink_to(file.name)
    else:
        os.link(file, link)
    return link.name


def assert_refused(run, option: str, holds: str = "catalogue") -> None:
    assert run.code == 2, (run.out, run.err)
    assert len(run.err.splitlines()) == 1, run.err
    assert f"{option}: would replace the {holds} " in run.err, run.err
    assert "Traceback" not in run.err


@pytest.mark.parametrize("way", WAYS)
@pytest.mark.parametrize("source", SOURCES)
@pytest.mark.parametrize("command", COMMANDS)
def test_an_output_naming_the_catalogue_is_refused(cli, shaft, tmp_path, command, source, way):
    extra = shaft(source)
    catalogue = tmp_path / "bearings.csv"
    before = fingerprint(catalogue)
    run = cli(*COMMANDS[command], *extra, "--output", target_naming(way, catalogue))
    assert_refused(run, "--output")
    assert fingerprint(catalogue) == before
    # nothing written beside it either: no temporary file left, no other output
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".")) == []


@pytest.mark.parametrize("command", ["sweep", "tolerance"])
@pytest.mark.parametrize("way", ["symlink", "hardlink"])
def test_a_plot_naming_the_catalogue_is_refused(cli, shaft, tmp_path, command, way):
    shaft("spec")
    catalogue = tmp_path / "bearings.csv"
    before = fingerprint(catalogue)
    args = COMMANDS[command] if command == "sweep" else ["tolerance", "shaft.yaml", "-m",
                                                          "monte-carlo", "-n", "256"]
    run = cli(*args, "--plot", target_naming(way, catalogue, ".svg"))
    assert_refused(run, "--plot")
    assert fingerprint(catalogue) == before


def test_the_refusal_names_the_catalogue_and_suggests_another_file(cli, shaft):
    shaft("spec")
    run = cli("select", "shaft.yaml", "--format", "csv", "--output", "bearings.csv")
    assert run.err == ("bearings.csv: --output: would replace the catalogue bearings.csv that "
                       "this run reads; write the selection to another file, like "
                       "bearings-select.csv\n")


def test_a_catalogue_named_by_option_is_refused_before_the_work(cli, shaft, monkeypatch):
    """--catalogue is an input whatever the specs name: refused before any spec is solved."""
    extra = shaft("option")

    def forbidden(*args, **kwargs):
        raise AssertionError("the work started before the outputs were checked")

    monkeypatch.setattr(batch, "check_files", forbidden)
    run = cli(*COMMANDS["check"], *extra, "--output", "bearings.csv")
    assert_refused(run, "--output")


def test_check_in_worker_processes_refuses_the_catalogue_they_read(cli, shaft, tmp_path,
                                                                   monkeypatch):
    """Specs checked in a pool: the catalogue a worker reads is the run's input too."""
    shaft("spec")
    for i in range(3):
        shutil.copyfile(tmp_path / "shaft.yaml", tmp_path / f"shaft-{i}.yaml")
    monkeypatch.setattr(batch, "PARALLEL_THRESHOLD", 2)
    catalogue = tmp_path / "bearings.csv"
    before = fingerprint(catalogue)
    run = cli("check", ".", "-j", "2", "-f", "json", "--output",
              target_naming("hardlink", catalogue))
    assert_refused(run, "--output")
    assert fingerprint(catalogue) == before


def test_a_table_shipped_with_the_package_is_an_input_too(cli, shaft, tmp_path):
    """The ISO table that checks catalogue rows is read by the run: no output replaces it."""
    import bearingcalc.data

    table = Path(bearingcalc.data.__file__).parent / TABLE
    before = fingerprint(table)
    shaft("spec")
    (tmp_path / "iso.csv").symlink_to(table)
    run = cli(*COMMANDS["sweep"], "--output", "iso.csv")
    assert_refused(run, "--output", "ISO table")
    assert fingerprint(table) == before


def test_an_output_beside_the_catalogue_is_written(cli, shaft, tmp_path):
    shaft("spec")
    run = cli("select", "shaft.yaml", "--format", "csv", "--output", "chosen.csv")
    assert run.code == 0, run.err
    assert (tmp_path / "chosen.csv").read_text().startswith("spec,position,rank")


def test_reads_are_kept_only_inside_a_run(tmp_path):
    """Outside a command's run (the Python API) nothing is kept; a run's notes end with it."""
    reads.note(tmp_path / "a.yaml", "spec")
    assert reads.noted() == {}
    with reads.tracking() as files:
        reads.note(tmp_path / "a.yaml", "spec")
        reads.note(tmp_path / "a.yaml", "catalogue")  # the first word for a file stays
        assert reads.noted() == {str(tmp_path / "a.yaml"): "spec"} == files
    assert reads.noted() == {}


def test_nested_runs_keep_their_own_notes(tmp_path):
    with reads.tracking() as outer:
        with reads.tracking() as inner:
            assert inner == outer == {}  # equal, yet each its own
        reads.note(tmp_path / "b.csv", "catalogue")
        assert reads.noted() == {str(tmp_path / "b.csv"): "catalogue"} == outer
    assert reads.noted() == {}
