"""The reports of ``check``: a verdict per spec as a table, JSON Lines or JUnit XML."""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from typing import IO, TYPE_CHECKING, Any

from bearingcalc.reports.formatting import console, format_number, safe_text
from bearingcalc.verdicts import verdict_line
from bearingcalc.wording import plural, printable

if TYPE_CHECKING:  # the report type only; its module loads with the command
    from bearingcalc.batch import CheckRecord


def check_record_json(record: CheckRecord) -> dict[str, Any]:
    """The JSON object of one check verdict."""
    from bearingcalc.reports.solve import verdict_record

    return {"spec": record.spec, "kind": record.kind, "name": record.name,
            **record.sources, "status": record.status, "messages": record.messages,
            "margins": record.margins,
            "verdicts": [verdict_record(verdict) for verdict in record.verdicts]}


def write_check_json_lines(records: Iterable[CheckRecord], stream: IO[str]) -> None:
    """One JSON object per verdict per line; non-finite numbers are refused."""
    for record in records:
        stream.write(json.dumps(check_record_json(record), allow_nan=False,
                                ensure_ascii=False) + "\n")


def write_junit(records: Sequence[CheckRecord], stream: IO[str]) -> None:
    """JUnit XML: one testcase per spec; ``fail`` as failure, ``invalid`` as error."""
    from xml.etree import ElementTree

    failures = sum(r.status == "fail" for r in records)
    errors = sum(r.status == "invalid" for r in records)
    suites = ElementTree.Element("testsuites", name="bearingcalc check", tests=str(len(records)),
                                 failures=str(failures), errors=str(errors))
    suite = ElementTree.SubElement(suites, "testsuite", name="bearingcalc check",
                                   tests=str(len(records)), failures=str(failures),
                                   errors=str(errors), skipped="0")
    for record in records:
        case = ElementTree.SubElement(suite, "testcase", classname=record.kind or "spec",
                                      name=printable(record.spec),
                                      file=printable(record.spec.split("#")[0]))
        text = "\n".join(printable(message) for message in record.messages)
        if record.status == "fail":
            ElementTree.SubElement(case, "failure", message=printable(_first(record.messages)),
                                   type="limit").text = text
        elif record.status == "invalid":
            ElementTree.SubElement(case, "error", message=printable(_first(record.messages)),
                                   type="invalid").text = text
    ElementTree.indent(suites)
    stream.write('<?xml version="1.0" encoding="UTF-8"?>\n')
    stream.write(ElementTree.tostring(suites, encoding="unicode") + "\n")


def print_check_table(records: Sequence[CheckRecord], *, show_all: bool,
                      stream: IO[str] | None = None, many: int = 50) -> None:
    """One row per spec (only fail/invalid rows past ``many`` specs unless ``show_all``),
    then a summary line with the counts."""
    from rich.table import Table

    out = console(stream)
    shown = records if show_all or len(records) <= many else [
        r for r in records if r.status != "pass"]
    colours = {"pass": "green", "fail": "red", "invalid": "magenta"}
    rows = [(f"[{colours[record.status]}]{record.status.upper()}[/]", safe_text(record.spec),
             safe_text(record.name or ""), record.kind or "",
             safe_text(_without_source(_detail(record), record.spec))) for record in shown]
    headers = ("status", "file", "name", "kind", "governing margin / problem")
    # status, file, name and kind on one line each, and at least 30 columns for the rest
    needed = sum(max([len(headers[i]), *(len(row[i]) for row in rows)]) + 3
                 for i in range(1, 4)) + 9 + 30
    if rows and needed <= out.width:
        table = Table(show_edge=False)
        for column in headers:
            table.add_column(column, overflow="fold", no_wrap=column != headers[-1])
        for row in rows:
            table.add_row(*row)
        out.print(table)
    else:  # a narrow terminal: a spec per paragraph, the verdict on its own line
        from rich.padding import Padding

        for status, spec, name, kind, detail in rows:
            # The file name is never broken by a line end, however long its path: the
            # line is left whole (a terminal folds it), to be read and copied as it is.
            out.print(f"{status}  {spec}  {name} ({kind})" if kind else f"{status}  {spec}",
                      soft_wrap=True)
            out.print(Padding(detail, (0, 0, 0, 6), expand=False))
    counts = {status: sum(r.status == status for r in records)
              for status in ("pass", "fail", "invalid")}
    hidden = len(records) - len(shown)
    note = f" ({hidden} passing not shown; --all shows them)" if hidden else ""
    out.print(f"{plural(len(records), 'spec')}: [green]{counts['pass']} pass[/], "
              f"[red]{counts['fail']} fail[/], "
              f"[magenta]{counts['invalid']} invalid[/]{note}")


def _detail(record: CheckRecord) -> str:
    """What decided the record: its governing verdict, or its first problem."""
    governing = record.governing_margin
    if record.status == "invalid":
        return _first(record.messages)
    if governing is None:
        return "no limits judged"
    if record.verdicts:
        return verdict_line(record.verdicts[0])
    return f"{governing[0]} = {format_number(governing[1])}"


def _without_source(message: str, source: str) -> str:
    """A problem without its leading 'file:' (the file column says it), keeping ':line:'."""
    return message[len(source):].lstrip(":") if message.startswith(source + ":") else message


def _first(messages: Sequence[str]) -> str:
    return messages[0] if messages else ""
