"""``python -m bearingcalc``."""

from bearingcalc.cli import app

app(prog_name="bearingcalc")
