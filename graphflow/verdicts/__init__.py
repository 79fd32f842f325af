"""Verdicts: a graph's checks, the one checked run, ``graphflow test`` and the pytest plugin."""
