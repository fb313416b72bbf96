"""Data shipped with bearingcalc: the ISO boundary dimensions of common bearing series."""
