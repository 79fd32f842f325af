"""``graphflow sweep``: many episodes of one graph over overrides and seeds, on a local pool or Ray."""
