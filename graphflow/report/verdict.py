"""The verdict as the report shows it: every check with pass or fail, and where on the timeline a failure belongs."""
from __future__ import annotations

import re

_AT_TIME = re.compile(r"\bat t = (-?[0-9.]+) s")


def tick_at(times: list[float], seconds: float) -> int:
    """The first tick whose time is at or after *seconds* (the last tick when the run ended before)."""
    for tick, time in enumerate(times):
        if tick and time >= seconds - 1e-9:
            return tick
    return len(times) - 1


def check_entries(evaluator, times: list[float], runtime_failure: str | None = None) -> list[dict]:
    """One entry per check in document order; a failure is placed at the time its measurement names,
    else at the check's own time, else at the run's end (checks judged at the end); ``passed`` is None for
    checks a run-time failure left unjudged."""
    failures = {failure.check: failure for failure in (evaluator.failures or ())}
    judged = evaluator.failures is not None   # a run that failed before its end judged no check
    entries = []
    for check in evaluator.checks:
        failure = failures.get(f"{check.index + 1} '{check.label}'")
        entry = {"index": check.index, "label": check.label, "passed": failure is None if judged else None,
                 "measured": None, "expected": None, "t": None, "tick": None}
        if failure is not None:
            named = _AT_TIME.search(failure.measured)
            seconds = float(named.group(1)) if named else (float(check.at) if check.at != "end" else times[-1])
            tick = tick_at(times, seconds)
            entry.update(measured=failure.measured, expected=failure.expected, t=times[tick], tick=tick)
        entries.append(entry)
    if runtime_failure is not None:
        entries.append({"index": len(entries), "label": "the run ends without a run-time failure", "passed": False,
                        "measured": runtime_failure, "expected": "no node fails", "t": times[-1],
                        "tick": len(times) - 1})
    return entries
