"""The flows' shared Python helpers (issue 62): one reader per format and one runner.

  vcd      a VCD file's declarations (timescale, scopes, variables) and its value changes
  liberty  a Liberty file's groups, its cells (pins, capacitances, internal power tables,
           leakage, area) and the table lookup OpenSTA does
  run      a command run to its end; a failure is one line, "PROG: WHAT failed (STATUS):
           STDERR", and exit status 1

The scripts stay files run as `python3 path/to/script.py`; each finds this package through
one line that puts scripts/ on sys.path (docs/flows.md).
"""
