"""The calculation report: valid HTML5 with nothing outside it, every result the JSON's
number, the spec verbatim; printed by a real browser where one is installed."""

from __future__ import annotations

import json
import os
import re
import shutil

import html5lib
import pytest

from tests.chromium_pipe import Chromium
from tests.conftest import ROOT

EXAMPLES = sorted((ROOT / "specs").glob("*.yaml"))


def _report(cli, path, tmp_path):
    target = tmp_path / f"{path.stem}.html"
    run = cli("report", path, "-o", target)
    assert run.code == 0, run.err
    return target.read_text(encoding="utf-8")


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda path: path.stem)
def test_the_report_is_html5_with_the_json_numbers(cli, tmp_path, path):
    page = _report(cli, path, tmp_path)
    html5lib.HTMLParser(strict=True).parse(page)  # raises on any parse error
    # nothing outside the file: no scripts, links, images or external addresses
    assert not re.search(r"<(script|link|img|iframe)\b", page)
    assert not [ref for ref in re.findall(r'(?:src|href)="([^"]*)"', page)
                if not ref.startswith("#")]
    records = [json.loads(line) for line in cli("solve", path, "--format", "json"
                                                ).out.splitlines()]
    cells = re.findall(r'data-key="([^"]+)" data-si="([^"]*)">([^<]*)<', page)
    expected = {(key, "null" if value is None else repr(value))
                for record in records for key, value in record["results"].items()}
    # the JSON's number to the last digit, and on the page to ten digits
    assert sorted((key, si) for key, si, _ in cells) == sorted(expected)
    for key, si, shown in cells:
        if si != "null":
            assert float(shown) == pytest.approx(float(si), rel=1e-9, abs=0), key
            assert len(shown) <= 16, shown
    assert path.read_text(encoding="utf-8").splitlines()[0].replace("&", "&amp;").replace(
        "<", "&lt;").replace(">", "&gt;").replace('"', "&quot;").replace("'", "&#x27;") in page


def test_a_bearing_report_plots_its_life_against_its_load(cli, tmp_path):
    page = _report(cli, ROOT / "specs" / "rolling-bearing.yaml", tmp_path)
    assert page.count("<svg") == 1 and "required life" in page
    drive = _report(cli, ROOT / "specs" / "bevel-drive-duty-cycle.yaml", tmp_path)
    assert drive.count("<svg") == 2  # the damage per bin and the bearings' lives


def test_a_bad_spec_is_one_line_and_no_file(cli, tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("kind: thrust-bearing\nball_diameter: 12.7\n")
    target = tmp_path / "bad.html"
    run = cli("report", bad, "-o", target)
    assert run.code == 2 and run.err.count("\n") >= 1 and not target.exists()


def test_a_browser_prints_each_report(cli, tmp_path):
    """Every example's report printed to PDF and shot to PNG, each page a tab of one
    headless Chromium (one launch for all: about two seconds saved a page)."""
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if browser is None:
        # CI installs it and sets the variable, so there the test cannot quietly skip.
        if os.environ.get("BEARINGCALC_REQUIRE_BROWSER"):
            pytest.fail("headless Chromium is required here and is not installed")
        pytest.skip("no headless Chromium here (Debian's chromium package)")
    from matplotlib.image import imread

    with Chromium(browser, tmp_path / "profile") as chromium:
        for path in EXAMPLES:
            page = tmp_path / f"{path.stem}.html"
            page.write_text(_report(cli, path, tmp_path), encoding="utf-8")
            pdf, png = chromium.print_page(page.as_uri(), width=1240, height=1754)
            assert pdf.startswith(b"%PDF-") and len(pdf) > 5000, path.name
            shot = tmp_path / f"{path.stem}.png"
            shot.write_bytes(png)
            assert imread(shot).std() > 0.01, path.name  # not a blank page
