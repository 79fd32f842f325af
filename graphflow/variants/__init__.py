"""Variants of a run: ``--set`` overrides and seeded randomizations, applied without editing files."""
