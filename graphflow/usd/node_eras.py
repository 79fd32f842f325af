"""Bundle nodes of omni.graph.nodes whose files changed meaning without a new typeVersion, or whose older
versions read a value differently (from the extension's changelog and the nodes' ``updateNodeVersion`` code).

* ``ReadPrims`` of omni.graph.nodes 1.82.6-1.89 (Kit 105.0) searched under ``inputs:rootPrims`` whenever
  ``pathPattern`` was set; 1.90 moved that node to ``ReadPrimsV2`` (its roots renamed ``inputs:prims``) and
  restored the older ``ReadPrims``. A ``ReadPrims`` file with ``rootPrims`` is that node: it loads as
  ``ReadPrimsV2``, rootPrims -> prims (``useFindPrims``, gone then, is dropped).
* ``WritePrims`` of 1.83.4-1.87 wrote under target prims: ``inputs:parentPrims`` (exported under them, appending
  each source path), renamed ``inputs:prims`` in 1.86 with ``scatterUnderTargets`` choosing between writing into
  the targets and under them; 1.88 moved that node to ``WritePrimsV2``. Such a file loads as ``WritePrimsV2``,
  parentPrims -> prims with ``scatterUnderTargets`` on (the only mode parentPrims had).
* ``ReadPrim`` and ``ReadPrimBundle`` before version 6 read every attribute when ``attrNamesToImport`` was empty;
  since version 6 ``"*"`` says so and an empty pattern matches nothing (their updateNodeVersion rewrites it).

Each mapping is one line naming the node and what was mapped.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass(frozen=True)
class Era:
    """Ports only an era's files of *type_id* have (*markers*), the node type hosting that era now, its renames."""

    markers: frozenset[str]
    now: str
    renames: dict[str, str | None]
    implied: dict[str, Any] = field(default_factory=dict)   # inputs the era fixed, set when the file leaves them
    when: str = ""


ERAS: dict[str, tuple[Era, ...]] = {
    "omni.graph.nodes.ReadPrims": (
        Era(frozenset({"inputs:rootPrims"}), "omni.graph.nodes.ReadPrimsV2",
            {"inputs:rootPrims": "inputs:prims", "inputs:useFindPrims": None}, when="omni.graph.nodes 1.82.6-1.89"),),
    "omni.graph.nodes.WritePrims": (
        Era(frozenset({"inputs:parentPrims"}), "omni.graph.nodes.WritePrimsV2", {"inputs:parentPrims": "inputs:prims"},
            {"scatterUnderTargets": True}, when="omni.graph.nodes 1.83.4-1.85"),
        Era(frozenset({"inputs:prims", "inputs:scatterUnderTargets"}), "omni.graph.nodes.WritePrimsV2", {},
            when="omni.graph.nodes 1.86-1.87")),
}

# node type -> the first version whose attrNamesToImport spells "every attribute" "*" (before it: "")
EMPTY_MEANT_EVERY_ATTRIBUTE = {"omni.graph.nodes.ReadPrim": 6, "omni.graph.nodes.ReadPrimBundle": 6}


def era_of(type_id: str, ports: set[str], where: str, warnings: list[str]) -> Era | None:
    """The era a node of *type_id* with these authored or connected *ports* comes from (one line), or None."""
    for era in ERAS.get(type_id, ()):
        if era.markers & ports:
            moved = [f"{old} -> {new}" if new else f"{old} dropped" for old, new in sorted(era.renames.items())
                     if old in ports]
            moved += [f"inputs:{name} = {value!r} (that era's only mode)" for name, value in era.implied.items()
                      if f"inputs:{name}" not in ports]
            warnings.append(f"{where}: {type_id} with {', '.join(sorted(era.markers & ports))} is the node of "
                            f"{era.when}, which Kit now names {era.now}: loaded as {era.now}"
                            + (f" ({', '.join(moved)})" if moved else ""))
            return era
    return None


def era_inputs(era: Era, inputs: dict[str, Any]) -> dict[str, Any]:
    """*inputs* with what the era fixed and the file left unset."""
    return {**{name: value for name, value in era.implied.items() if name not in inputs}, **inputs}


def upgraded_values(type_id: str, version: int | None, inputs: dict[str, Any], where: str,
                    warnings: list[str]) -> dict[str, Any]:
    """*inputs* as the node's current version reads what an older *version* meant (one line per value changed)."""
    since = EMPTY_MEANT_EVERY_ATTRIBUTE.get(type_id)
    if since is None or version is None or version >= since or inputs.get("attrNamesToImport") != "":
        return inputs
    warnings.append(f"{where}: inputs:attrNamesToImport \"\" -> \"*\" (before version {since} of {type_id} an empty "
                    "pattern read every attribute; since, \"*\" does)")
    return {**inputs, "attrNamesToImport": "*"}
