"""Watching a run from outside: traces, timeline plots, graph pictures."""
