"""Tests of graphflow's physics area (a package so test module names stay unique)."""
