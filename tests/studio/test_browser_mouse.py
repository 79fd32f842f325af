"""The page's mouse events as a source of the mouse service: delivered at the next poll, replayed exactly when saved."""
import pytest

from graphflow.errors import BadInput
from graphflow.inputs.mouse import attach_mouse
from graphflow.studio.browser_input import BrowserMouse
from graphflow.testing import NodeHarness

ON_MOUSE = "omni.graph.action.OnMouseInput"


def test_page_clicks_fire_at_the_next_step_and_the_delivered_timeline_replays_them():
    mouse = BrowserMouse()
    live = NodeHarness(ON_MOUSE, time_step=0.1)
    attach_mouse(live.world, mouse)
    fired = [sorted(live.tick().fired)]
    mouse.event("Left Button", 1)
    fired.append(sorted(live.tick().fired))
    fired.append(sorted(live.tick().fired))
    mouse.event("Left Button", 0)
    fired.append(sorted(live.tick().fired))
    assert fired == [[], ["pressed"], [], ["released"]]
    replay = NodeHarness(ON_MOUSE, time_step=0.1)
    attach_mouse(replay.world, mouse.timeline())
    assert [sorted(replay.tick().fired) for _ in range(4)] == fired


def test_a_bad_page_event_is_refused_with_the_reason():
    with pytest.raises(BadInput, match="unknown mouse element 'Wheel'"):
        BrowserMouse().event("Wheel", 1)
    with pytest.raises(BadInput, match="Position is normalized"):
        BrowserMouse().event("Position", [2.0, 0.5])
