"""Every public function of the Python API refuses a wrong argument, whatever its type or
value, with a SpecError naming the argument and what it takes: never a TypeError or an
AttributeError from inside. And a SpecError carries every problem of a spec."""

from __future__ import annotations

import math

import numpy as np
import pytest
import yaml

import bearingcalc
from bearingcalc.errors import ArgumentError, Problem, SpecError
from tests.conftest import ROOT

SPEC = ROOT / "specs" / "thrust-bearing.yaml"
STUDY = ROOT / "specs" / "tolerances" / "thrust-bearing.yaml"
#: Values of every type a caller may pass by mistake.
HOSTILE = [None, True, 0, -1, 5, 2.5, math.nan, math.inf, "", " ", "many", "\0", b"x",
           bytearray(b"x"), [], [1], ["x"], (), {}, {"x": 1}, {1: 2}, object(), 1j,
           np.float64(3.0), np.int64(-3), {"kind": 5}]


def _study(**arguments):
    return bearingcalc.tolerance(STUDY, **{"samples": 64, **arguments})


@pytest.fixture(scope="module")
def line():
    return bearingcalc.sweep(SPEC, {"contact_angle": "10deg:40deg:4"})


@pytest.fixture(scope="module")
def study():
    return _study()


@pytest.fixture(scope="module")
def result():
    return bearingcalc.solve(SPEC)[0]


def _calls(line, study, result):
    """Each public function and method with one argument left free: (name, call)."""
    return {
        "solve.spec": bearingcalc.solve,
        "tolerance.spec": lambda value: bearingcalc.tolerance(value, samples=64),
        "tolerance.methods": lambda value: _study(methods=value),
        "tolerance.samples": lambda value: _study(samples=value),
        "tolerance.seed": lambda value: _study(seed=value),
        "tolerance.sampler": lambda value: _study(sampler=value),
        "tolerance.results": lambda value: _study(results=value),
        "sweep.spec": lambda value: bearingcalc.sweep(value, {"contact_angle": "10deg:40deg:3"}),
        "sweep.vary": lambda value: bearingcalc.sweep(SPEC, value),
        "Result.quantity.key": result.quantity,
        "Study.plot.key": lambda value: study.plot(None, value),
        "Study.plot.path": study.plot,
        "Sweep.plot.results": lambda value: line.plot(None, value),
        "Sweep.plot.path": line.plot,
    }


@pytest.mark.parametrize("value", HOSTILE, ids=repr)
def test_every_argument_takes_any_value_without_an_internal_error(value, line, study, result,
                                                                  tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a plot given a path that works is drawn here
    for name, call in _calls(line, study, result).items():
        try:
            call(value)
        except SpecError as error:
            assert str(error) and all(error.lines()), name
        except Exception as error:  # the point of the test: nothing else escapes
            pytest.fail(f"{name}({value!r}) raised {type(error).__name__}: {error}")


@pytest.mark.parametrize(("call", "function", "argument"), [
    (lambda: bearingcalc.solve(None), "solve", "spec"),
    (lambda: bearingcalc.solve(5), "solve", "spec"),
    (lambda: bearingcalc.solve(b"kind: thrust-bearing\n"), "solve", "spec"),
    (lambda: bearingcalc.solve([SPEC, SPEC]), "solve", "spec"),
    (lambda: bearingcalc.solve(""), "solve", "spec"),
    (lambda: bearingcalc.solve("kind: thrust-bearing\0"), "solve", "spec"),
    (lambda: bearingcalc.sweep(SPEC, "radial_load=1kN:2kN:3"), "sweep", "vary"),
    (lambda: bearingcalc.sweep(SPEC, {}), "sweep", "vary"),
    (lambda: bearingcalc.sweep(SPEC, {"a": "1:2:3", "b": "1:2:3", "c": "1:2:3"}), "sweep",
     "vary"),
    (lambda: bearingcalc.sweep(SPEC, {"contact_angle": 5}), "sweep", "vary"),
    (lambda: _study(samples="many"), "tolerance", "samples"),
    (lambda: _study(samples=-5), "tolerance", "samples"),
    (lambda: _study(samples=1), "tolerance", "samples"),
    (lambda: _study(samples=2.5), "tolerance", "samples"),
    (lambda: _study(samples=2**30 + 1), "tolerance", "samples"),
    (lambda: _study(samples=10**10 + 1, sampler="random"), "tolerance", "samples"),
    (lambda: _study(methods=["worst-case", "montecarlo"]), "tolerance", "methods"),
    (lambda: _study(methods=[]), "tolerance", "methods"),
    (lambda: _study(methods=5), "tolerance", "methods"),
    (lambda: _study(sampler="halton"), "tolerance", "sampler"),
    (lambda: _study(seed=-1), "tolerance", "seed"),
    (lambda: _study(seed="x"), "tolerance", "seed"),
    (lambda: _study(results=["slip_margn"]), "tolerance", "results"),
    (lambda: _study(results=[5]), "tolerance", "results"),
    (lambda: bearingcalc.solve(SPEC)[0].quantity("pitch_radus"), "Result.quantity", "key"),
])
def test_a_bad_argument_is_named_with_what_it_takes(call, function, argument):
    with pytest.raises(ArgumentError) as raised:
        call()
    error = raised.value
    assert isinstance(error, SpecError) and isinstance(error, ValueError)
    assert (error.source, error.field) == (f"{function}()", argument)
    assert str(error).startswith(f"{function}(): {argument}: ")
    assert len(error.lines()) == 1


def test_the_message_says_what_the_argument_takes():
    with pytest.raises(ArgumentError, match=r"samples: a whole number from 2 to "):
        _study(samples="many")
    with pytest.raises(ArgumentError, match=r"one of 'worst-case', 'rss', 'monte-carlo', "
                                            r"got 'montecarlo' \(did you mean 'monte-carlo'"):
        _study(methods="worst-case,montecarlo")
    with pytest.raises(ArgumentError, match=r"like \{\"radial_load\": \"1kN:2kN:3\"\}"):
        bearingcalc.sweep(SPEC, "radial_load=1kN:2kN:3")
    with pytest.raises(ArgumentError, match=r"sampler='random' takes more"):
        _study(samples=2**31)
    with pytest.raises(ArgumentError, match=r"decode the bytes"):
        bearingcalc.solve(b"kind: thrust-bearing")


def test_a_method_or_result_may_be_one_text_or_a_list(study):
    one = _study(methods="rss")
    assert list(one.record["results"]["slip_margin"]) == ["nominal", "rss"]
    listed = _study(methods="worst-case, rss", results="slip_margin")
    assert {"worst_case", "rss"} <= set(listed.record["results"]["slip_margin"])
    assert _study(samples=64.0).record["samples"] == 64  # 1e5 is a number of samples too


def test_a_missing_file_a_folder_and_a_text_that_names_no_file(tmp_path):
    for spec, said in [(tmp_path / "none.yaml", "no such file"),
                       (str(tmp_path / "none.yaml"), "no such file"),
                       ("C:\\specs\\drive.yaml", "no such file"),
                       (tmp_path, "is a folder"), (str(tmp_path), "is a folder"),
                       ("thrust-bearing", "no such file")]:
        with pytest.raises(SpecError) as raised:
            bearingcalc.solve(spec)
        assert said in str(raised.value) and not isinstance(raised.value, ArgumentError)


def test_a_mapping_that_is_not_a_spec_is_refused_at_its_field():
    spec = yaml.safe_load(SPEC.read_text())
    cases = [({**spec, "ball_diameter": object()}, "ball_diameter"),
             ({**spec, "limits": {"max_spin_to_roll": {1, 2}}}, "limits.max_spin_to_roll"),
             ({**spec, 5: "x"}, None), ({"kind": {"a": [1, {2: 3}]}}, "kind.a.2")]
    looped: dict = {**spec}
    looped["limits"] = {"inner": looped}
    cases.append((looped, "limits.inner"))
    deep: dict = {}
    inner = deep
    for _ in range(40):
        inner["a"] = inner = {}
    cases.append(({**spec, "x": deep}, "x" + ".a" * 19))
    for mapping, field in cases:
        with pytest.raises(SpecError) as raised:
            bearingcalc.solve(mapping)
        assert raised.value.field == field and raised.value.source == "<mapping>"
    with pytest.raises(SpecError) as raised:  # a mapping that holds no spec
        bearingcalc.solve({"a": 1})
    assert raised.value.field == "kind"


def test_numpy_numbers_in_a_mapping_are_numbers():
    spec = {**yaml.safe_load((ROOT / "specs" / "ball-bearing.yaml").read_text())}
    plain = bearingcalc.solve(spec)[0]
    counted = {key: np.int64(value) if isinstance(value, int) and not isinstance(value, bool)
               else value for key, value in spec.items()}
    assert bearingcalc.solve(counted)[0].results == plain.results


def test_a_plot_path_is_a_png_or_svg_in_a_folder_that_exists(line, tmp_path):
    for path in [tmp_path / "chart.txt", tmp_path / "missing" / "chart.png", tmp_path,
                 5, b"chart.png"]:
        with pytest.raises(ArgumentError) as raised:
            line.plot(path)
        assert raised.value.field == "path"
    assert not list(tmp_path.iterdir())  # nothing was written


def test_a_study_without_monte_carlo_has_no_histogram():
    with pytest.raises(ArgumentError, match="monte-carlo"):
        _study(methods="rss").plot()


# --- every problem of a spec ------------------------------------------------------------


def _typo_and_bad_value() -> dict:
    spec = yaml.safe_load(SPEC.read_text())
    spec["ball_diameter"] = "12.7"            # no unit
    spec["nmae"] = spec.pop("name")           # a typo
    return spec


def test_the_message_holds_every_problem_and_problems_give_them_as_data():
    with pytest.raises(SpecError) as raised:
        bearingcalc.solve(_typo_and_bad_value())
    error = raised.value
    problems = error.problems
    assert len(problems) == 2 and all(isinstance(problem, Problem) for problem in problems)
    assert {problem.field for problem in problems} == {"ball_diameter", "nmae"}
    assert str(error).splitlines() == error.lines() == [str(p) for p in problems]
    for problem in problems:
        assert problem.file == "<mapping>" and isinstance(problem.line, int)
        assert str(problem) == f"<mapping>:{problem.line}: {problem.field}: {problem.message}"
    assert error.first == problems[0]


def test_the_command_line_prints_the_same_lines(cli, tmp_path):
    path = tmp_path / "spec.yaml"
    path.write_text(yaml.safe_dump(_typo_and_bad_value(), sort_keys=False))
    with pytest.raises(SpecError) as raised:
        bearingcalc.solve(path)
    assert cli("solve", path).err.splitlines() == str(raised.value).splitlines()
    assert len(raised.value.problems) == 2


def test_a_problem_of_a_whole_file_has_no_line_or_field(tmp_path):
    with pytest.raises(SpecError) as raised:
        bearingcalc.solve(tmp_path / "none.yaml")
    (problem,) = raised.value.problems
    assert (problem.line, problem.field) == (None, None)
    assert str(problem) == str(raised.value)


def test_a_bad_range_of_a_sweep_is_a_bad_vary():
    for vary, said in [({"contact_angle": "10deg:40deg:1"}, "contact_angle: N must be at least 2"),
                       ({"contact_angle": "10:40deg:3"}, "contact_angle: '10' has no unit"),
                       ({"contact_angel": "10deg:40deg:3"}, "contact_angel: "),
                       ({"contact_angle": "10deg"}, "contact_angle: '10deg': write START:STOP:N")]:
        with pytest.raises(ArgumentError) as raised:
            bearingcalc.sweep(SPEC, vary)
        assert str(raised.value).startswith(f"sweep(): vary: {said}"), str(raised.value)
        assert "--vary" not in str(raised.value)


def test_every_documents_problems_are_raised_together():
    text = SPEC.read_text()
    several = "---\n".join([text.replace("12.7 mm", "12.7"), text,
                            text.replace("30 deg", "30")])
    with pytest.raises(SpecError) as raised:
        bearingcalc.solve(several)
    problems = raised.value.problems
    assert [(p.file, p.field) for p in problems] == [("<string>#1", "ball_diameter"),
                                                      ("<string>#3", "contact_angle")]
