"""docs/nodes.md is generated from the node specs: it must match them, and the command must write it safely."""

from conftest import ROOT

from graphflow.catalog.markdown import REGENERATE_COMMAND, render_markdown
from graphflow.cli import main
from graphflow.registry import Registry, default_registry
from graphflow.spec import Attribute, NodeSpec, NodeType

DOCS = ROOT / "docs" / "nodes.md"


def test_docs_nodes_md_matches_the_registered_specs():
    expected = render_markdown(default_registry())
    current = DOCS.read_text(encoding="utf-8") if DOCS.exists() else ""
    assert current == expected, f"docs/nodes.md is stale: regenerate it with `{REGENERATE_COMMAND}`"


def test_a_node_section_lists_every_port_with_type_default_and_bounds():
    registry = Registry()
    registry.register(NodeType(spec=NodeSpec(
        id="test.Pump", version=2, description="Pumps at a rate.", ui_name="Pump", categories=("fluids",),
        aliases=("old.Pump",), compatible_versions=(1,),
        inputs=(Attribute("execIn", "execution", description="Pump once"),
                Attribute("rate", "double", default=0.5, minimum=0.0, maximum=2.0, description="Litres | second"),
                Attribute("mode", "token", default="low", allowed_tokens=("low", "high"), description="Speed")),
        outputs=(Attribute("pumped", "double[]", description="Volumes so far"),),
        state=(Attribute("total", "double", description="Litres pumped"),)),
        compute=lambda db: None, module="tests.pump"))
    text = render_markdown(registry)
    assert "| [test.Pump](#testpump) | Pump | 2 | exec |" in text
    assert "**Pump** · version 2 · exec · categories `fluids` · module `tests.pump`" in text
    assert "Also loads as `old.Pump`." in text and "Files of typeVersion 1 load as version 2." in text
    assert "| `inputs:rate` | `double` | `0.5` | 0 to 2 | Litres \\| second |" in text
    assert "| `inputs:mode` | `token` | `\"low\"` | `low`, `high` | Speed |" in text
    assert "| `outputs:pumped` | `double[]` | `[]` |  | Volumes so far |" in text
    assert "| `state:total` | `double` | `0.0` |  | Litres pumped |" in text


def test_the_command_prints_writes_and_never_overwrites_without_force(tmp_path, capsys):
    assert main(["nodes", "--markdown"]) == 0
    assert capsys.readouterr().out == render_markdown(default_registry())
    target = tmp_path / "nodes.md"
    assert main(["nodes", "--markdown", "-o", str(target)]) == 0
    assert target.read_text(encoding="utf-8") == render_markdown(default_registry())
    target.write_text("hand edits", encoding="utf-8")
    assert main(["nodes", "--markdown", "-o", str(target)]) == 2
    assert "already exists" in capsys.readouterr().err
    assert target.read_text(encoding="utf-8") == "hand edits"
    assert main(["nodes", "--markdown", "-o", str(target), "--force"]) == 0
    assert target.read_text(encoding="utf-8") == render_markdown(default_registry())
    assert sorted(p.name for p in tmp_path.iterdir()) == ["nodes.md"]   # no temporary file left behind
