"""Bearing catalogues: designations, the ISO boundary dimensions shipped with bearingcalc,
catalogue files of the user's, and filling a spec's bearings from them.

- :mod:`~bearingcalc.catalogue.designation`: a designation's basic part and suffixes,
  and ISO 15's bore code;
- :mod:`~bearingcalc.catalogue.iso`: the shipped table of boundary dimensions;
- :mod:`~bearingcalc.catalogue.reader`: reading a catalogue CSV file, hardened;
- :mod:`~bearingcalc.catalogue.catalogue`: its rows in SI, checked against ISO, and the
  lookup of a designation;
- :mod:`~bearingcalc.catalogue.fill`: a spec's bearings filled from their catalogue rows.
"""
