"""``graphflow validate`` and ``run``'s preflight: what can be known about a graph without running it."""
