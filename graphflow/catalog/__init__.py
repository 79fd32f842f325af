"""The node catalog: what the registered node specs say, published as docs/nodes.md."""
