"""Issue 15: property-based fuzzing of the graph file path, end to end through the command.

Hypothesis generates graph documents from the registered node types: real attribute
names and connections between real ports most of the time (so documents get past
validation and run), random values, names, settings and text damage the rest of the
time. Each document is written to a file and goes through ``graphflow validate`` and
``graphflow run --ticks 3`` in this process (no stage: ClockWorld graphs, so it is fast).

The properties: no crash (exit code 0, 1 or 2; never the last-resort "unexpected error",
never a traceback), every error one line, and no hang (a small ``stepBudget`` bounds every
tick; nothing is timed). Derandomized so CI sees the same documents every run; set
GRAPHFLOW_FUZZ_EXAMPLES=5000 GRAPHFLOW_FUZZ_RANDOM=1 to explore further locally.
"""
import contextlib
import io
import json
import os
import string

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphflow import cli
from graphflow.files import FileProblem, loads_strict
from graphflow.registry import default_registry
from graphflow.types import SCALAR_KINDS, can_connect, element_type, parse_type

EXAMPLES = int(os.environ.get("GRAPHFLOW_FUZZ_EXAMPLES", "500"))
FUZZ = settings(max_examples=EXAMPLES, deadline=None, database=None,
                derandomize="GRAPHFLOW_FUZZ_RANDOM" not in os.environ,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
SPECS = [node_type.spec for node_type in default_registry().types()]

scalars = st.one_of(
    st.none(), st.booleans(),
    st.integers(min_value=-(2**70), max_value=2**70),
    st.sampled_from([0, 1, -1, 3, 2**31, 2**32, 2**63, 10**6]),
    st.floats(allow_nan=False, allow_infinity=False),
    st.sampled_from(["", "inf", "nan", "-inf", "/World", "World/ur10", "/World/Cube", "{value}", "{}", "{0[0]}",
                     "count = {value:.3f}", "Info", "Warning", ">=", "==", "auto", "double[]", "A", "Space",
                     "a\nb", "\u00e9\u00e8", "\ud7ff"]),
    st.text(max_size=12),
)
json_values = st.recursive(scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=5), st.dictionaries(st.text(max_size=6), inner, max_size=3)), max_leaves=12)
names = st.one_of(st.sampled_from(["tick", "count", "branch", "a", "b", "node_1", "x-y"]),
                  st.text(alphabet=string.ascii_letters + string.digits + "_-.\n :", min_size=0, max_size=8))


def typed_values(attribute):
    """Values of an attribute's own type (within its range and tokens), sometimes anything at all."""
    attr_type = attribute.attr_type
    if attribute.allowed_tokens:
        fitting = st.sampled_from(attribute.allowed_tokens)
    else:
        fitting = _values_of(attr_type, attribute.minimum, attribute.maximum)
    return st.one_of(fitting, fitting, fitting, json_values)


def _values_of(attr_type, low=None, high=None):
    if attr_type.is_any:
        return scalars
    if attr_type.is_target:
        return st.sampled_from(["/World", "/World/Cube", ["/World/a", "/World/b"]])
    if attr_type.is_array:
        return st.lists(_values_of(element_type(attr_type), low, high), max_size=4)
    kind = SCALAR_KINDS.get(attr_type.base)
    if kind == "bool":
        one = st.booleans()
    elif kind in ("int", "uint"):
        one = st.integers(min_value=0 if low is None else int(low), max_value=20 if high is None else int(high))
    elif kind == "real":
        one = st.floats(min_value=-1e3 if low is None else low, max_value=1e3 if high is None else high)
    else:
        one = st.one_of(st.text(max_size=8), st.sampled_from(["/World", "{value}", "count {}", ""]))
    if attr_type.tuple_size:
        return st.lists(one, min_size=attr_type.tuple_size, max_size=attr_type.tuple_size)
    return one


def rarely(draw) -> bool:
    """True about one time in ten (Hypothesis leans to small integers, so the rare case is the large one)."""
    return draw(st.integers(0, 9)) == 9


@st.composite
def documents(draw):
    """A graph document: mostly well-formed parts, each possibly wrong in one way."""
    chaos = rarely(draw) or rarely(draw)   # about one document in five gets wrong parts here and there

    def wrong() -> bool:
        return chaos and rarely(draw)

    count = draw(st.integers(min_value=0, max_value=7))
    specs = [draw(st.sampled_from(SPECS)) for _ in range(count)]
    node_names = [draw(names) if wrong() else f"n{i}" for i in range(count)]
    nodes = []
    for name, spec in zip(node_names, specs):
        node = {"name": name, "type": draw(st.text(max_size=30)) if wrong() else spec.id}
        inputs = {}
        for _ in range(draw(st.integers(0, 3))):
            settable = [a for a in spec.inputs if not a.is_execution]
            if settable and not wrong():
                attribute = draw(st.sampled_from(settable))
                inputs[attribute.name] = draw(typed_values(attribute))
            elif wrong():
                inputs[draw(names)] = draw(json_values)
        if inputs:
            node["inputs"] = inputs
        if wrong():
            node["typeVersion"] = draw(st.integers(-1, 5))
        nodes.append(node)
    connections = []
    for _ in range(draw(st.integers(0, 10)) if count else 0):
        # mostly forward (src before dst: no data cycles) between ports whose types connect
        src, dst = sorted((draw(st.integers(0, count - 1)), draw(st.integers(0, count - 1))))
        if wrong():
            src, dst = dst, src
        if src == dst and not wrong():
            continue
        outputs = [a for a in specs[src].outputs]
        src_attribute = draw(st.sampled_from(outputs)) if outputs else None
        inputs = [a for a in specs[dst].inputs
                  if src_attribute is None or can_connect(src_attribute.attr_type, a.attr_type) or wrong()]
        src_attr = src_attribute.name if src_attribute else "x"
        if not inputs and not wrong():
            continue
        dst_attr = draw(st.sampled_from(inputs)).name if inputs else "y"
        connections.append({"src": f"{node_names[src]}.outputs:{src_attr}", "dst": f"{node_names[dst]}.inputs:{dst_attr}"}
                           if not wrong() else {"src": draw(st.text(max_size=15)), "dst": draw(st.text(max_size=15))})
    document = {"format": "graphflow", "formatVersion": [draw(st.integers(1, 2)) if wrong() else 1, draw(st.integers(0, 3))], "nodes": nodes,
                "settings": {"timeStep": draw(st.sampled_from([0.5, 0.1, 1 / 60, 1e-9, 1.0])),
                             "stepBudget": draw(st.integers(1, 300)),
                             "duration": draw(st.sampled_from([1.0, 0.25, 1e7, 1e308]))}}
    if connections:
        document["connections"] = connections
    if wrong() or wrong() or wrong():
        variables = []
        for index in range(draw(st.integers(1, 3))):
            type_name = draw(st.sampled_from(["int", "uint", "double", "float", "bool", "token", "string", "double[3]",
                                              "int[]", "execution", "target", "any", "quatd[4]", "nonsense"]))
            default = draw(_values_of(parse_type(type_name))) if type_name not in ("execution", "nonsense") and \
                not wrong() else draw(json_values)
            variables.append({"name": draw(names) if wrong() else f"v{index}", "type": type_name,
                              "default": default})
        document["variables"] = variables
    if wrong():   # a field that does not belong, or a setting out of range
        document[draw(st.sampled_from(["ui", "description", "settings", "extra"]))] = draw(json_values)
    return document


def damaged(text: str, data) -> str:
    """The text with one small edit: a cut, a duplicated key, a literal JSON does not have, or none."""
    choice = data.draw(st.integers(0, 11)) - 8   # 0 to 3: damaged, about one document in three
    if choice == 3 and text:
        cut = data.draw(st.integers(0, len(text) - 1))
        return text[:cut] + text[cut + 1:]
    if choice == 1:
        return text.replace('"nodes":', '"nodes": [], "nodes":', 1)
    if choice == 2:
        return text.replace('"stepBudget":', '"stepBudget": NaN, "x":', 1)
    return text


def command(*args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main(list(args))
    return code, out.getvalue(), err.getvalue()


def assert_clean_failure(code: int, err: str, allowed: tuple[int, ...]) -> None:
    assert code in allowed, (code, err)
    assert "unexpected error" not in err and "Traceback" not in err, err
    for line in err.splitlines():   # every error is one line naming the file, or a run-time line naming the node
        assert line.startswith(("graphflow: error: ", "graphflow: run-time error: ", "WARNING", "ERROR")) or ": run-time failure: " in line \
            or ".json: " in line, line


@FUZZ
@given(document=documents(), data=st.data())
def test_generated_documents_never_crash_or_hang(tmp_path_factory, document, data):
    folder = tmp_path_factory.mktemp("fuzz", numbered=True)
    path = folder / "graph.json"
    text = damaged(json.dumps(document, ensure_ascii=data.draw(st.booleans())), data)
    path.write_text(text, encoding="utf-8", errors="surrogatepass")

    code, _out, err = command("validate", str(path))
    assert_clean_failure(code, err, (0, 2))
    code_run, _out, err = command("run", str(path), "--ticks", "3")
    assert_clean_failure(code_run, err, (0, 1, 2))
    assert (code == 0) == (code_run in (0, 1)), "validate and run's load must agree"


@FUZZ
@given(text=st.one_of(st.text(max_size=200), st.text(alphabet='{}[]",:0123456789.eE+-truefalsnNaIiy\\u ', max_size=80)))
def test_any_text_is_json_or_one_line_file_problem(text):
    try:
        loads_strict(text, "fuzz.json")
    except FileProblem as problem:
        assert "\n" not in str(problem) and str(problem).startswith("fuzz.json: ")
