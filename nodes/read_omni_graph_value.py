"""omni.graph.nodes.ReadOmniGraphValue: a node's or a prim's attribute read by name, without a connection."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadOmniGraphValue",
    version=1,
    description=(
        "outputs:value = the attribute 'name' of what 'path' names. A node of this graph (graphflow import "
        "turns Kit's node path, /World/ActionGraph/add, into the node's name, add; a hand-written graph gives "
        "the name): its attribute ('outputs:sum', 'inputs:a', 'state:count') as that node holds it now, i.e. as "
        "it last computed (a pure node nothing pulled yet holds its defaults), as Kit reads it from Fabric "
        "without computing it. Otherwise a prim path ('/World/Cube'): the prim's attribute as the world has it "
        "now (what ReadPrimAttribute reads). No such node, prim or attribute fails the run with a line naming "
        "it. path is a string here (it may name a node, which a USD path type could not); only an authored "
        "path is turned into a node name on import, so a node path that arrives through a connection is read "
        "as a prim path."),
    categories=("sceneGraph",),
    ui_name="Read OmniGraph Value",
    inputs=(
        Attribute("name", "token", default="", description="The attribute to read ('outputs:sum', 'size')"),
        Attribute("path", "string", default="",
                  description="A node of this graph (its name) or a prim (its path) that holds the attribute"),
    ),
    outputs=(
        Attribute("value", "any", description="The attribute's value"),
    ),
)


def compute(db):
    path, name = db.inputs.path, db.inputs.name
    if not path:
        db.error("inputs:path is empty: name a node of this graph or a prim")
    if not name:
        db.error("inputs:name is empty: name the attribute to read")
    try:
        db.outputs.value = db.world.get_attribute(path, name) if path.startswith("/") else db.node_value(path, name)
    except KeyError as error:
        db.error(str(error.args[0]))
    except WorldError as error:
        db.error(str(error))
