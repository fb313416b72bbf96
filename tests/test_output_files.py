"""Output files: never one of the run's inputs, written all or none; stdout write errors."""

from __future__ import annotations

import errno
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from bearingcalc import batch, plots, reports, studies, sweeps
from tests.conftest import ROOT

#: Thrust bearing with tolerances: every command takes it.
TOLERANCED = ROOT / "specs" / "tolerances" / "thrust-bearing.yaml"
VARY = ("--vary", "contact_angle=10deg:40deg:4")
STUDY = ("-m", "monte-carlo", "-n", "1024")


def command_args(command: str, spec: str | Path) -> list[str]:
    """A quick run of ``command`` on ``spec``, before any --output or --plot."""
    extra = {"sweep": VARY, "tolerance": STUDY}.get(command, ())
    return [command, str(spec), *extra]


def fingerprint(path: Path) -> tuple[bytes, int]:
    return path.read_bytes(), path.stat().st_mtime_ns


@pytest.fixture
def no_work(monkeypatch):
    """Make the work of every command fail loudly: a refusal must come before it."""
    def forbidden(*args, **kwargs):
        raise AssertionError("the work started before the outputs were checked")

    monkeypatch.setattr(sweeps, "run_sweep", forbidden)
    monkeypatch.setattr(studies, "run_study", forbidden)
    monkeypatch.setattr(batch, "check_files", forbidden)


def assert_refused(run, option: str) -> None:
    assert run.code == 2, (run.out, run.err)
    lines = run.err.splitlines()
    assert len(lines) == 1, run.err
    assert option in lines[0] and "Traceback" not in run.err


def name_the_spec(way: str, tmp_path: Path, suffix: str) -> tuple[str, Path, Path]:
    """A spec in ``tmp_path`` and two names of it: (the spec argument, the output target,
    the spec file). ``suffix`` is the spec file's suffix, so that a --plot target, which
    must end in .png or .svg, can name it too."""
    spec = tmp_path / f"spec{suffix}"
    shutil.copyfile(TOLERANCED, spec)
    argument, target = str(spec), spec
    if way == "dotdot":
        (tmp_path / "x").mkdir()
        target = Path(f"{tmp_path}/x/../{spec.name}")
    elif way == "symlink":
        target = tmp_path / f"link{suffix}"
        target.symlink_to(spec)
    elif way == "relative-symlink":
        target = tmp_path / f"link{suffix}"
        target.symlink_to(spec.name)
    elif way == "hardlink":
        target = tmp_path / f"hard{suffix}"
        os.link(spec, target)
    elif way == "document":
        argument = f"{spec}#1"
    return argument, target, spec


WAYS = ["same", "dotdot", "symlink", "relative-symlink", "hardlink", "document"]


@pytest.mark.parametrize("way", WAYS)
@pytest.mark.parametrize(("command", "option"), [
    ("sweep", "--output"), ("sweep", "--plot"),
    ("tolerance", "--output"), ("tolerance", "--plot"),
    ("check", "--output"),
])
def test_an_output_naming_the_spec_is_refused(cli, tmp_path, no_work, way, command, option):
    argument, target, spec = name_the_spec(way, tmp_path, ".png" if option == "--plot"
                                           else ".yaml")
    before = fingerprint(spec)
    run = cli(*command_args(command, argument), option, target)
    assert_refused(run, option)
    assert "would replace the spec" in run.err
    assert fingerprint(spec) == before
    if "symlink" in way:
        assert target.is_symlink()


def test_the_refusal_names_the_file_and_suggests_another(cli, tmp_path, no_work):
    spec = tmp_path / "drive.yaml"
    shutil.copyfile(TOLERANCED, spec)
    run = cli("sweep", spec, *VARY, "-o", spec)
    assert run.err == (f"{spec}: --output: would replace the spec {spec} that this run "
                       "reads; write the results to another file, like drive-sweep.csv\n")


@pytest.mark.parametrize("how", ["folder", "glob", "deep-glob", "link-in-folder"])
def test_check_refuses_an_output_naming_a_spec_it_finds(cli, tmp_path, no_work, how):
    designs = tmp_path / "designs"
    (designs / "sub").mkdir(parents=True)
    spec = designs / "sub" / "a.yaml"
    shutil.copyfile(TOLERANCED, spec)
    shutil.copyfile(TOLERANCED, designs / "b.yaml")
    target = spec
    if how == "link-in-folder":
        # The output is a link elsewhere to a spec the folder holds.
        target = tmp_path / "report.json"
        target.symlink_to(spec)
    path = {"glob": f"{designs}/sub/*.yaml", "deep-glob": f"{designs}/**/*.yaml"
            }.get(how, str(designs))
    before = fingerprint(spec)
    run = cli("check", path, "--output", target)
    assert_refused(run, "--output")
    assert fingerprint(spec) == before


def test_check_takes_an_output_beside_the_specs_it_finds(cli, tmp_path):
    shutil.copyfile(TOLERANCED, tmp_path / "a.yaml")
    run = cli("check", tmp_path, "-f", "json", "-o", tmp_path / "report.jsonl")
    assert run.code == 0, run.err
    assert '"status": "pass"' in (tmp_path / "report.jsonl").read_text()


@pytest.mark.parametrize("way", WAYS)
def test_solve_reads_the_spec_by_any_name_and_leaves_it_alone(cli, tmp_path, way):
    argument, target, spec = name_the_spec(way, tmp_path, ".yaml")
    before = fingerprint(spec)
    for name in {argument, str(target)}:
        run = cli("solve", name, "-f", "json")
        assert run.code == 0, run.err
    assert fingerprint(spec) == before
    assert cli("solve", argument, "--output", tmp_path / "out.json").code == 2


# --- every target is checked before the work, and written all or none ---------------------

def bad_target(kind: str, tmp_path: Path, name: str) -> Path:
    """A target that cannot be written, of ``kind``."""
    if kind == "folder":
        (tmp_path / "folder").mkdir()
        return tmp_path / "folder"
    if kind == "missing-folder":
        return tmp_path / "no" / "such" / name
    if kind == "file-as-folder":
        (tmp_path / "notes.txt").write_text("a file")
        return tmp_path / "notes.txt" / name
    raise ValueError(kind)


BAD = ["folder", "missing-folder", "file-as-folder"]
MULTI = [("sweep", "results.csv"), ("tolerance", "report.json")]


@pytest.mark.parametrize("bad", BAD)
@pytest.mark.parametrize(("command", "report"), MULTI)
def test_an_unwritable_output_leaves_an_existing_plot_alone(cli, tmp_path, no_work, bad,
                                                            command, report):
    plot = tmp_path / "chart.png"
    plot.write_bytes(b"earlier chart")
    before = fingerprint(plot)
    run = cli(*command_args(command, TOLERANCED), "--plot", plot,
              "--output", bad_target(bad, tmp_path, report))
    assert_refused(run, "--output")
    assert fingerprint(plot) == before


@pytest.mark.parametrize("bad", BAD)
@pytest.mark.parametrize(("command", "report"), MULTI)
def test_an_unwritable_plot_leaves_an_existing_output_alone(cli, tmp_path, no_work, bad,
                                                            command, report):
    output = tmp_path / report
    output.write_text("earlier results\n")
    before = fingerprint(output)
    run = cli(*command_args(command, TOLERANCED), "--output", output,
              "--plot", bad_target(bad, tmp_path, "chart.png"))
    assert_refused(run, "--plot")
    assert fingerprint(output) == before


@pytest.mark.parametrize("command", ["sweep", "tolerance", "check"])
def test_a_folder_without_write_permission_is_refused_before_the_work(cli, tmp_path, no_work,
                                                                      monkeypatch, command):
    locked = tmp_path / "locked"
    locked.mkdir()
    real_access = os.access
    # The tests may run as root, whom chmod would not stop.
    monkeypatch.setattr(os, "access", lambda path, mode: (
        Path(path).resolve() != locked.resolve() and real_access(path, mode)))
    run = cli(*command_args(command, TOLERANCED), "--output", locked / "out.json")
    assert_refused(run, "--output")
    assert "permission denied" in run.err


@pytest.mark.parametrize("link", [False, True])
@pytest.mark.parametrize(("command", "report"), MULTI)
def test_an_output_that_is_the_plot_is_refused(cli, tmp_path, no_work, link, command, report):
    plot = tmp_path / "chart.png"
    plot.write_bytes(b"earlier chart")
    output = plot
    if link:
        output = tmp_path / "also-chart.png"
        output.symlink_to(plot)
    run = cli(*command_args(command, TOLERANCED), "--output", output, "--plot", plot)
    assert_refused(run, "--plot")
    assert plot.read_bytes() == b"earlier chart"


def broken_writer(*args, **kwargs):
    """A report writer or plot drawer (its stream is the last argument) that fails halfway."""
    stream = args[-1]
    stream.write(b"half" if "b" in getattr(stream, "mode", "") else "half a line")
    raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))


@pytest.mark.parametrize(("command", "report", "writer"), [
    ("sweep", "results.csv", (reports, "write_sweep_csv")),
    ("tolerance", "report.txt", (reports, "print_tolerance_table")),
])
def test_an_output_failing_while_written_leaves_the_plot_alone(cli, tmp_path, monkeypatch,
                                                               command, report, writer):
    plot, output = tmp_path / "chart.png", tmp_path / report
    plot.write_bytes(b"earlier chart")
    output.write_text("earlier results\n")
    before = fingerprint(plot), fingerprint(output)
    monkeypatch.setattr(*writer, broken_writer)
    run = cli(*command_args(command, TOLERANCED), "--plot", plot, "--output", output)
    assert (fingerprint(plot), fingerprint(output)) == before
    assert_refused(run, "--output")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([plot.name, output.name])


@pytest.mark.parametrize(("command", "report", "drawer"), [
    ("sweep", "results.csv", "sweep_plot"),
    ("tolerance", "report.json", "tolerance_histogram"),
])
def test_a_plot_failing_while_drawn_leaves_the_output_alone(cli, tmp_path, monkeypatch,
                                                            command, report, drawer):
    plot, output = tmp_path / "chart.png", tmp_path / report
    plot.write_bytes(b"earlier chart")
    output.write_text("earlier results\n")
    before = fingerprint(plot), fingerprint(output)
    monkeypatch.setattr(plots, drawer, broken_writer)
    run = cli(*command_args(command, TOLERANCED), "--output", output, "--plot", plot)
    assert (fingerprint(plot), fingerprint(output)) == before
    assert_refused(run, "--plot")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([plot.name, output.name])


@pytest.mark.parametrize("existing", [True, False])
@pytest.mark.parametrize(("command", "report"), MULTI)
def test_an_output_failing_while_renamed_puts_the_plot_back(cli, tmp_path, monkeypatch,
                                                            existing, command, report):
    plot, output = tmp_path / "chart.png", tmp_path / report
    if existing:
        plot.write_bytes(b"earlier chart")
        output.write_text("earlier results\n")
        before = fingerprint(plot), fingerprint(output)
    rename = os.replace

    def replace(source, destination):
        if Path(destination).name == report and Path(source).name.endswith(".tmp"):
            raise OSError(errno.EBUSY, os.strerror(errno.EBUSY))
        rename(source, destination)

    monkeypatch.setattr(os, "replace", replace)
    run = cli(*command_args(command, TOLERANCED), "--plot", plot, "--output", output)
    if existing:
        assert (fingerprint(plot), fingerprint(output)) == before
        assert sorted(p.name for p in tmp_path.iterdir()) == sorted([plot.name, output.name])
    else:
        assert list(tmp_path.iterdir()) == []
    assert_refused(run, "--output")


@pytest.mark.parametrize(("command", "report"), MULTI)
def test_a_successful_run_writes_both(cli, tmp_path, command, report):
    plot, output = tmp_path / "chart.png", tmp_path / report
    plot.write_bytes(b"earlier chart")
    output.write_text("earlier results\n")
    run = cli(*command_args(command, TOLERANCED), "--output", output, "--plot", plot)
    assert run.code == 0, run.err
    assert plot.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    assert output.read_text() != "earlier results\n" and output.stat().st_size > 100
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([plot.name, output.name])


def test_a_plot_with_the_report_on_a_device_or_through_a_link(cli, tmp_path):
    real = tmp_path / "real.png"
    real.write_bytes(b"earlier chart")
    link = tmp_path / "chart.png"
    link.symlink_to(real)
    run = cli("sweep", TOLERANCED, *VARY, "-f", "csv", "--output", "/dev/null", "--plot", link)
    assert run.code == 0, run.err
    assert link.is_symlink() and real.read_bytes().startswith(b"\x89PNG")


# --- standard output that cannot be written ------------------------------------------------

FULL = Path("/dev/full")


@pytest.mark.skipif(not FULL.exists(), reason="no /dev/full on this system")
@pytest.mark.parametrize("command", ["solve", "check", "tolerance", "sweep"])
def test_a_full_stdout_is_one_line_and_status_2(tmp_path, command):
    plot = tmp_path / "chart.png"
    plot.write_bytes(b"earlier chart")
    args = command_args(command, TOLERANCED)
    if command in ("sweep", "tolerance"):
        args += ["--plot", str(plot)]
    with FULL.open("wb") as full:
        done = subprocess.run([sys.executable, "-m", "bearingcalc", *args], stdout=full,
                              stderr=subprocess.PIPE, text=True, timeout=120, check=False)
    assert done.returncode == 2, done.stderr
    assert done.stderr == f"cannot write the output: {os.strerror(errno.ENOSPC).lower()}\n"
    # The run failed, so the plot it would have drawn is not there either.
    assert plot.read_bytes() == b"earlier chart"


@pytest.mark.skipif(not FULL.exists(), reason="no /dev/full on this system")
def test_an_output_on_a_full_device_is_one_line_naming_the_option(cli):
    run = cli("check", TOLERANCED, "--output", FULL)
    assert_refused(run, "--output")
    assert os.strerror(errno.ENOSPC).lower() in run.err


@pytest.mark.parametrize("command", ["sweep", "check"])
def test_a_closed_pipe_still_keeps_the_exit_status(tmp_path, command):
    failing = tmp_path / "failing.yaml"
    failing.write_text(TOLERANCED.read_text().replace("max_spin_to_roll: 0.01",
                                                      "max_spin_to_roll: 0.0001"))
    args = " ".join(command_args(command, failing))
    done = subprocess.run(
        f"{sys.executable} -m bearingcalc {args} | head -c 1 >/dev/null; "
        "echo ${PIPESTATUS[0]}", shell=True, executable="/bin/bash", capture_output=True,
        text=True, timeout=120, check=False)
    assert done.stdout.strip() == ("0" if command == "sweep" else "1"), done
    assert done.stderr == ""
