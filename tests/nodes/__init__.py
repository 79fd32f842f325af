"""Tests of graphflow's nodes area (a package so test module names stay unique)."""
