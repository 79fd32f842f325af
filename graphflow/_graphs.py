"""The few directed-graph algorithms loading a graph needs, on plain dicts (no networkx import).

Importing networkx costs about as much as the rest of ``graphflow run`` on a
core-node graph, so loading and compiling use these instead. A graph here is
``{node: set of successors}`` (every node a key); node values are plain
hashables (names, indices). Results match networkx's where both exist:
``lexicographical_topological_sort`` is Kahn's algorithm with a min-heap, as in
``networkx.lexicographical_topological_sort`` with its default key.
"""
from __future__ import annotations

import heapq
from typing import Hashable, Iterable

Graph = dict  # {node: set of successor nodes}


def predecessors_of(graph: Graph) -> dict:
    """{node: set of predecessor nodes}."""
    predecessors = {node: set() for node in graph}
    for node, successors in graph.items():
        for successor in successors:
            predecessors[successor].add(node)
    return predecessors


def reachable(neighbours: dict, start: Hashable, allowed=None) -> set:
    """Nodes reachable from *start* (not *start* itself, unless on a cycle) along *neighbours*,
    stepping only onto nodes for which ``allowed(node)`` is true (every node when None)."""
    reached, frontier = set(), [start]
    while frontier:
        for neighbour in neighbours[frontier.pop()]:
            if neighbour not in reached and (allowed is None or allowed(neighbour)):
                reached.add(neighbour)
                frontier.append(neighbour)
    return reached


def lexicographical_topological_sort(graph: Graph, nodes: Iterable[Hashable]) -> list:
    """The nodes in topological order of the subgraph they induce, smallest available node first."""
    members = set(nodes)
    indegree = dict.fromkeys(members, 0)
    for node in members:
        for successor in graph[node]:
            if successor in members:
                indegree[successor] += 1
    ready = [node for node, degree in indegree.items() if degree == 0]
    heapq.heapify(ready)
    order = []
    while ready:
        node = heapq.heappop(ready)
        order.append(node)
        for successor in graph[node]:
            if successor in members:
                indegree[successor] -= 1
                if indegree[successor] == 0:
                    heapq.heappush(ready, successor)
    if len(order) != len(members):
        raise ValueError("the graph has a cycle")
    return order


def has_cycle(graph: Graph) -> bool:
    """True when some node can reach itself (self-loops included)."""
    indegree = dict.fromkeys(graph, 0)
    for successors in graph.values():
        for successor in successors:
            indegree[successor] += 1
    ready = [node for node, degree in indegree.items() if degree == 0]
    seen = 0
    while ready:
        node = ready.pop()
        seen += 1
        for successor in graph[node]:
            indegree[successor] -= 1
            if indegree[successor] == 0:
                ready.append(successor)
    return seen != len(graph)
