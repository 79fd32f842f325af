"""Tests of graphflow's usd area (a package so test module names stay unique)."""
