"""``python interrupt_at.py N ARGS...``: ``python -m graphflow ARGS`` with a Ctrl-C (SIGINT) at its N-th Python event.

A profile hook counts call, return and C-call events from graphflow's first instruction (the events after
its package module's frame starts: nothing of graphflow ran before) and raises SIGINT in the process at the
N-th, so whatever handler is installed then handles it exactly as it would a Ctrl-C from the terminal.
N = 0 runs without interrupting and prints the number of events on stderr (the last line).
N = ``inside:MODULE`` raises it at the first import that MODULE's own loading starts (a C extension's
initialisation importing what it needs), and says on stderr at exit whether MODULE finished loading.
"""
import os
import runpy
import signal
import sys
from importlib.util import find_spec

PACKAGE = os.path.dirname(os.path.abspath(find_spec("graphflow").origin))   # located, not imported
INSIDE = sys.argv[1].removeprefix("inside:") if sys.argv[1].startswith("inside:") else None
limit = -1 if INSIDE else int(sys.argv[1])
count = 0
armed = False


def loading(frame, module: str) -> bool:
    """True when *frame* runs within the loading of *module* (its loader's create_module or exec_module)."""
    while frame is not None:
        spec = frame.f_locals.get("spec") if frame.f_code.co_name in ("create_module", "exec_module") else None
        if getattr(spec, "name", None) == module:
            return True
        frame = frame.f_back
    return False


def hook(frame, event, arg):
    global count, armed
    if not armed:   # the package's module frame starting is not yet an instruction of it
        armed = frame.f_code.co_filename.startswith(PACKAGE)
        return
    count += 1
    nested_import = INSIDE and event == "call" and frame.f_code.co_name == "_find_and_load" and loading(frame, INSIDE)
    if count == limit or nested_import:
        sys.setprofile(None)
        signal.raise_signal(signal.SIGINT)


if INSIDE:
    import atexit

    atexit.register(lambda: print(f"{INSIDE} loaded: {INSIDE in sys.modules}", file=sys.stderr))
if limit == 0:
    import atexit

    atexit.register(lambda: print(f"events: {count}", file=sys.stderr))
sys.argv = ["graphflow", *sys.argv[2:]]
signal.signal(signal.SIGINT, signal.default_int_handler)   # as in a terminal (a background job inherits "ignore")
sys.setprofile(hook)
runpy.run_module("graphflow", run_name="__main__", alter_sys=True)
