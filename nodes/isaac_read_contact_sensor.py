"""isaacsim.sensors.physics.IsaacReadContactSensor: is the body touched, and how hard.

csPrim is a contact sensor prim on a rigid body (or the body itself): the
node sums the normal forces of the body's contacts after the last physics
step. inContact is true when that sum is above zero.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError, on_nearest_ancestor

SPEC = NodeSpec(
    id="isaacsim.sensors.physics.IsaacReadContactSensor",
    version=1,
    aliases=("omni.isaac.isaac_sensor.IsaacReadContactSensor", "omni.isaac.sensor.IsaacReadContactSensor"),
    description=(
        "On execIn, reads the contacts of the rigid body carrying csPrim: inContact, and value = the total "
        "normal force (N)."),
    categories=("isaacSensor",),
    ui_name="Isaac Read Contact Sensor Node",
    inputs=(
        Attribute("execIn", "execution", description="Read the sensor"),
        Attribute("csPrim", "target", description="The contact sensor prim (or its rigid body)"),
        Attribute("useLatestData", "bool", default=False,
                  description="Ignored (deprecated in Isaac too): every reading is the latest physics step's"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the reading"),
        Attribute("inContact", "bool", description="The body touches something"),
        Attribute("value", "float", description="Total normal force, N"),
        Attribute("sensorTime", "float", description="Simulated time of the reading, s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.csPrim:
        db.error("inputs:csPrim is not set: no contact sensor to read")
    contacts = _contacts(db, db.inputs.csPrim[0])
    force = sum(float(contact[4]) for contact in contacts)
    db.outputs.value = force
    db.outputs.inContact = force > 0.0
    db.outputs.sensorTime = float(db.time)
    db.outputs.execOut = ExecState.ENABLED


def _contacts(db, path: str):
    """Contacts of *path*, or of its nearest ancestor that is a rigid body (a sensor prim sits under its body)."""
    try:
        return on_nearest_ancestor(path, db.world.contacts)[1]
    except WorldError as error:
        db.error(f"inputs:csPrim: {path} is not on a rigid body ({error})")
