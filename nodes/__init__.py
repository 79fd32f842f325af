"""Built-in node types of graphflow, one module per node type (import name ``graphflow_nodes``)."""
