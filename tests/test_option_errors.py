"""Every bad option value, whether the command line's parser or bearingcalc finds it, is
one line in the parser's own form: 'bearingcalc CMD: Invalid value for OPTION: what is
wrong (see 'bearingcalc CMD -h')', exit status 2."""

from __future__ import annotations

import re

import pytest

from bearingcalc import api
from bearingcalc.errors import SpecError
from tests.conftest import ROOT

SPECS = ROOT / "specs"
STUDY = str(SPECS / "tolerances" / "thrust-bearing.yaml")
ONE_INPUT = str(SPECS / "tolerances" / "bevel-gears.yaml")
SHAFT = str(SPECS / "rolling-bearing-catalogue.yaml")
VARY = ("--vary", "contact_angle=10deg:40deg:3")

#: (arguments, the option named, a fragment of what is wrong): each value checked by
#: bearingcalc itself, past the parser.
CHECKED_BY_THE_TOOL = [
    (["select", SHAFT, "--max-outside-diameter", "62"], "'--max-outside-diameter'", "no unit"),
    (["select", SHAFT, "--max-outside-diameter", "62 kN"], "'--max-outside-diameter'",
     "not a unit of length"),
    (["select", SHAFT, "--max-outside-diameter", "0 mm"], "'--max-outside-diameter'",
     "greater than zero"),
    (["select", SHAFT, "--max-width", "wide"], "'--max-width'", ""),
    (["select", SHAFT, "--type", "ball"], "'--type' / '-t'", "not a bearing type"),
    (["tolerance", STUDY, "--method", "exact"], "'--method' / '-m'", "unknown method 'exact'"),
    (["tolerance", STUDY, "--method", ","], "'--method' / '-m'", "names no method"),
    (["tolerance", STUDY, "--sampler", "halton"], "'--sampler'", "unknown sampler"),
    (["tolerance", STUDY, "-n", "2e9"], "'--samples' / '-n'", "distinct Sobol' points"),
    (["tolerance", STUDY, "--result", "speed"], "'--result' / '-r'", "'speed' is not a result"),
    (["tolerance", STUDY, "--plot", "x.pdf"], "'--plot'", "give a .png or .svg"),
    (["tolerance", STUDY, "-m", "rss", "--plot", "x.png"], "'--plot'", "add monte-carlo"),
    (["tolerance", STUDY, "-j", "100000"], "'--jobs' / '-j'", "per core"),
    (["sweep", STUDY, "--vary", "nope=1:2:3"], "'--vary' / '-v'", "has no input 'nope'"),
    (["sweep", STUDY, "--vary", "contact_angle=1:2"], "'--vary' / '-v'", "NAME=START:STOP:N"),
    (["sweep", STUDY, "--vary", "contact_angle=5deg:40deg:1"], "'--vary' / '-v'",
     "N must be at least 2"),
    (["sweep", STUDY, *VARY, *VARY], "'--vary' / '-v'", "given twice"),
    (["sweep", STUDY, *VARY, "--result", "spin"], "'--result' / '-r'", "'spin'"),
    (["sweep", STUDY, *VARY, "--plot", "x.gif"], "'--plot'", "give a .png or .svg"),
    (["sweep", STUDY, *VARY, "--format", "parquet"], "'--format' / '-f'",
     "give --output grid.parquet"),
    (["check", STUDY, "-j", "100000"], "'--jobs' / '-j'", "per core"),
    (["schema", "--kind", "thrust-bering"], "'--kind' / '-k'", "unknown kind"),
    (["new", "thrust-bering"], "'KIND'", "unknown kind"),
    (["new", "rolling-bearing", "--type", "ball"], "'--type'", "template"),
]
#: The same for values the parser checks: the form to match.
CHECKED_BY_THE_PARSER = [
    (["select", SHAFT, "--top", "0"], "'--top' / '-n'", "give a whole number"),
    (["tolerance", STUDY, "-n", "1"], "'--samples' / '-n'", "give a whole number"),
    (["sweep", STUDY, *VARY, "--format", "xls"], "'--format' / '-f'", ""),
]


@pytest.mark.parametrize(("args", "option", "fragment"),
                         CHECKED_BY_THE_TOOL + CHECKED_BY_THE_PARSER)
def test_a_bad_option_value_is_one_usage_line(cli, tmp_path, monkeypatch, args, option,
                                              fragment):
    monkeypatch.chdir(tmp_path)  # a plot or output that got written would land here
    run = cli(*args)
    command = args[0]
    assert run.code == 2, (run.out, run.err)
    assert run.err.count("\n") == 1, run.err
    line = run.err.rstrip("\n")
    assert re.fullmatch(rf"root {command}: Invalid value for {re.escape(option)}: .+ "
                        rf"\(see 'root {command} -h'\)", line), line
    assert fragment in line and "Traceback" not in line
    assert not list(tmp_path.iterdir())


def test_sobol_with_one_toleranced_input_is_a_usage_line(cli, tmp_path):
    text = (SPECS / "thrust-bearing.yaml").read_text()
    spec = tmp_path / "one.yaml"
    spec.write_text(re.sub(r"(?m)^contact_angle: (\S+ \S+)", r"contact_angle: \1 ± 0.5 deg",
                           text))
    assert "± 0.5 deg" in spec.read_text()
    run = cli("tolerance", spec, "--sobol", "-m", "monte-carlo", "-n", "256")
    assert run.code == 2 and run.err == (
        "root tolerance: Invalid value for '--sobol': needs at least two toleranced inputs "
        "(see 'root tolerance -h')\n"), run.err


def test_no_option_is_reported_as_a_problem_of_the_spec():
    """The class, by its source: a message that leads with an option's name is an
    OptionError (or a StudyError or SweepError naming the option), never a SpecError."""
    pattern = re.compile(r"""(?:SpecError|ValueError|print)\(\s*f?["'](?:error: )?--[a-z]""")
    offenders = [f"{path.relative_to(ROOT)}:{number}"
                 for path in (ROOT / "bearingcalc").rglob("*.py")
                 for number, line in enumerate(path.read_text().splitlines(), 1)
                 if pattern.search(line)]
    assert offenders == []


def test_the_python_api_still_raises_spec_error_naming_the_option():
    with pytest.raises(SpecError) as raised:
        api.sweep(str(SPECS / "thrust-bearing.yaml"), {"nope": "1:2:3"})
    # in the API's words: the argument is vary, not the command's --vary
    assert "--vary" not in str(raised.value)
    assert "nope: the spec has no input 'nope'" in str(raised.value)
