"""Kit's main timeline headless: what the Get/Set/Start/Stop/LoopTimeline nodes read and write.

Not a node type. A graphflow run's clock is the simulation's: the timeline's
current time is the simulated time since reset and it only moves forward, one
fixed step per tick. Its play range and rate start as the stage authors them
(startTimeCode, endTimeCode, timeCodesPerSecond; USD's fallbacks 0, 0 and 24
without them or without a stage); SetTimeline and LoopTimeline change them for
the run (a ``WorldService``: a reset returns to the stage's values). The range is
recorded and read back; a run's length stays graphflow's (--ticks, --seconds).
"""
from __future__ import annotations

FALLBACK_TIME_CODES_PER_SECOND = 24.0     # USD's fallback for an unauthored timeCodesPerSecond


class PlaybackTimeline:
    """The play range, rate, looping and playing flags of one world's run."""

    def __init__(self, world):
        self.world = world
        self.reset()

    def reset(self) -> None:
        stage = getattr(self.world, "stage", None)
        if stage is None:
            self.frames_per_second, start, end = FALLBACK_TIME_CODES_PER_SECOND, 0.0, 0.0
        else:
            self.frames_per_second = float(stage.GetTimeCodesPerSecond())
            start, end = float(stage.GetStartTimeCode()), float(stage.GetEndTimeCode())
        self.start_time, self.end_time = start / self.frames_per_second, end / self.frames_per_second
        self.looping = False
        self.playing = True

    def after_step(self, dt: float) -> None:
        """Nothing moves here: the time is the world's."""

    @property
    def time(self) -> float:
        return float(self.world.time)

    def frame_of(self, seconds: float) -> float:
        return seconds * self.frames_per_second

    def time_of(self, frame: float) -> float:
        return frame / self.frames_per_second


def timeline(db) -> PlaybackTimeline:
    world = db.world
    return world.services.require(PlaybackTimeline, lambda: PlaybackTimeline(world))
