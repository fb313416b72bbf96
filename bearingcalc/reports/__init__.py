"""Presenting results: rich tables (engineering units), JSON Lines, CSV, JUnit XML and
Parquet (SI).

One module per command's reports, beside what they share (``formatting``) and the
sweep's CSV writer (``sweep_csv``).
"""

from bearingcalc.reports.check import (
    check_record_json,
    print_check_table,
    write_check_json_lines,
    write_junit,
)
from bearingcalc.reports.formatting import PIPE_WIDTH, console, format_number, safe_text
from bearingcalc.reports.solve import (
    evaluation_record,
    print_tables,
    write_csv,
    write_json_lines,
)
from bearingcalc.reports.sweep import (
    print_sweep_table,
    write_sweep_json_lines,
    write_sweep_parquet,
)

# The private helpers are for tests/test_sweep.py, which compares the block writer
# with a line writer built from them.
from bearingcalc.reports.sweep_csv import _csv_block as _csv_block
from bearingcalc.reports.sweep_csv import _csv_text as _csv_text
from bearingcalc.reports.sweep_csv import _integer_fields as _integer_fields
from bearingcalc.reports.sweep_csv import sweep_columns, write_sweep_csv
from bearingcalc.reports.tolerance import print_tolerance_table, write_tolerance_json

__all__ = [
    "PIPE_WIDTH",
    "check_record_json",
    "console",
    "evaluation_record",
    "format_number",
    "print_check_table",
    "print_sweep_table",
    "print_tables",
    "print_tolerance_table",
    "safe_text",
    "sweep_columns",
    "write_check_json_lines",
    "write_csv",
    "write_json_lines",
    "write_junit",
    "write_sweep_csv",
    "write_sweep_json_lines",
    "write_sweep_parquet",
    "write_tolerance_json",
]
