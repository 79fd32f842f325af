"""Issue 26: fuzzing with values of the wrong JSON kind anywhere in a document.

The generator of ``test_hardening_fuzz`` makes documents of the right shape; here one to three places
in each (a node's name or type, an input name, a connection end, a variable, a check, the scenario, a
setting) get a value of any JSON kind (a list or an object where a name belongs was ``TypeError:
unhashable type``, "unexpected error", in 22 of 10,000 documents). Properties as there: exit 0, 1 or 2,
never "unexpected error", every error one line. ``GRAPHFLOW_FUZZ_EXAMPLES=10000`` for the full run.
"""
import json

from hypothesis import given
from hypothesis import strategies as st

from .test_hardening_fuzz import FUZZ, assert_clean_failure, command, documents, json_values

CHECKS = [
    {"check": "position", "prim": "/World/Cube", "position": [0, 0, 0], "tolerance": 0.01, "at": 0.5},
    {"check": "held", "gripper": "/World/G", "from": 0.1, "to": 0.2, "name": "held"},
    {"check": "stopsBy", "time": 0.5},
    {"check": "finite"},
]
ANY_KIND = st.one_of(st.lists(json_values, max_size=3), st.dictionaries(st.text(max_size=4), json_values, max_size=2),
                     json_values)


def places(document: dict) -> list[tuple]:
    """(container, key) pairs a wrong value can go into."""
    found: list[tuple] = [(document, "checks"), (document, "scenario")]
    settings = document.setdefault("settings", {})
    if isinstance(settings, dict):    # the generator may already have put a wrong kind there
        found.append((settings, "duration"))
    for node in document.get("nodes", []):
        found += [(node, "name"), (node, "type"), (node, "inputs")]
        found += [(node["inputs"], key) for key in node.get("inputs", {})]
    for connection in document.get("connections", []):
        found += [(connection, "src"), (connection, "dst")]
    for variable in document.get("variables", []):
        found += [(variable, "name"), (variable, "type")]
    for check in document.get("checks", []):
        found += [(check, key) for key in check]
    return found


@FUZZ
@given(document=documents(), data=st.data())
def test_a_value_of_the_wrong_kind_anywhere_is_a_clean_error(tmp_path_factory, document, data):
    document["checks"] = [dict(check) for check in data.draw(st.lists(st.sampled_from(CHECKS), max_size=3))]
    if data.draw(st.booleans()):
        document["scenario"] = {"seed": 1, "keys": ["A@0.1"], "topics": ['/t@0.1={"data": 1}']}
    spots = places(document)      # found before any change: a replaced part's old container is just left behind
    for _ in range(data.draw(st.integers(1, 3))):
        container, key = data.draw(st.sampled_from(spots))
        container[key] = data.draw(ANY_KIND)
    path = tmp_path_factory.mktemp("fuzz", numbered=True) / "graph.json"
    path.write_text(json.dumps(document), encoding="utf-8")
    code, _out, err = command("validate", str(path))
    assert_clean_failure(code, err, (0, 2))
    code_run, _out, err = command("run", str(path), "--ticks", "3")
    assert_clean_failure(code_run, err, (0, 1, 2))
