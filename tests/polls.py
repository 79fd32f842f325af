"""Driving a watch from a test: each poll of the watcher makes the next scripted edit, then Ctrl-C."""


class Script:
    """A sleep that does the next scripted edit instead of waiting (None: nothing happens this poll)."""

    def __init__(self, *edits):
        self.edits, self.polls = list(edits), 0

    def __call__(self, _seconds):
        self.polls += 1
        if not self.edits:
            raise KeyboardInterrupt   # the script is over: Ctrl-C
        edit = self.edits.pop(0)
        if edit is not None:
            edit()
