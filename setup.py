"""Packages are found, not listed: graphflow's whole tree, plus nodes/ installed under the import name graphflow_nodes.

pyproject.toml's ``packages.find`` cannot rename a folder, so this one call does it; everything else is in pyproject.toml.
"""
from setuptools import find_packages, setup

setup(packages=[*find_packages(include=["graphflow", "graphflow.*"]), "graphflow_nodes"],
      package_dir={"graphflow_nodes": "nodes"})
