"""String helpers shared by the omni.graph.nodes string nodes (AppendString, BuildString)."""
from graphflow_nodes._math import plain


def appended(db, head, tail):
    """head + tail for strings, or tail appended to each string of an array head."""
    head, tail = plain(head), plain(tail)
    if not isinstance(tail, str):
        db.error(f"the string to append must be a string or token, got {tail!r}")
    if isinstance(head, str):
        return head + tail
    if isinstance(head, tuple) and all(isinstance(item, str) for item in head):
        return tuple(item + tail for item in head)
    db.error(f"the string to append to must be a string, token or token array, got {head!r}")
