"""Where episodes run: a ``Launcher`` takes episodes and yields their records as they finish.

*What* runs is the episode (``graphflow.sweep.episode``); *where* is the launcher's business: a local
process pool (``LocalPool``) or Ray actors (``RayPool``). A later launcher (a cluster queue) implements
the same ``run(episodes) -> records`` and ``close()``. A worker or actor that dies fails only its episode.
"""
from __future__ import annotations

from collections import deque
from typing import Generator, Sequence

from graphflow.errors import EXTRAS, MissingExtra
from graphflow.sweep.definition import Episode, Sweep, SweepError
from graphflow.sweep.episode import EpisodeRunner, failed_record, quiet_logging

# ------------------------------------------------------------------ executors: local pool and Ray

def _worker_main(connection, sweep: Sweep) -> None:
    """A pool worker: builds one runner, then runs the episodes it is sent until it gets None."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)   # Ctrl-C is the parent's to handle
    quiet_logging()
    runner = None
    try:
        runner = EpisodeRunner(sweep)
        connection.send(("ready", None))
        while True:
            episode = connection.recv()
            if episode is None:
                break
            try:
                record = runner.run(episode)
            except Exception as error:   # the episode fails with its reason; the worker goes on
                record = failed_record(episode, f"worker error: {type(error).__name__}: {error}", sweep.metric_names)
            connection.send(("done", record))
    except (EOFError, BrokenPipeError, KeyboardInterrupt):
        pass
    except Exception as error:
        connection.send(("broken", f"{type(error).__name__}: {error}"))
    finally:
        if runner is not None:
            runner.close()


class LocalPool:
    """``jobs`` worker processes (spawned: no state shared with the parent), one episode in flight each.

    A worker that dies fails the episode it was running (its exit code or
    signal is the reason) and is replaced; the other episodes go on.
    """

    def __init__(self, sweep: Sweep, jobs: int):
        import multiprocessing

        self.sweep = sweep
        self.jobs = jobs
        self.context = multiprocessing.get_context("spawn")
        self.workers: list[dict] = []

    def _start_worker(self) -> dict:
        parent, child = self.context.Pipe()
        process = self.context.Process(target=_worker_main, args=(child, self.sweep), daemon=True)
        process.start()
        child.close()
        worker = {"process": process, "connection": parent, "episode": None, "ready": False}
        self.workers.append(worker)
        return worker

    def run(self, episodes: Sequence[Episode]) -> Generator[dict, None, None]:
        from multiprocessing.connection import wait

        pending = list(reversed(episodes))
        for _ in range(min(self.jobs, len(episodes))):
            self._start_worker()
        try:
            while pending or any(w["episode"] is not None for w in self.workers):
                for worker in list(self.workers):
                    if worker["ready"] and worker["episode"] is None and pending:
                        try:
                            worker["connection"].send(pending[-1])
                        except (BrokenPipeError, OSError):
                            continue   # it died idle; wait() reports its end next
                        worker["episode"] = pending.pop()
                ready = wait([w["connection"] for w in self.workers])
                for worker in [w for w in self.workers if w["connection"] in ready]:
                    try:
                        kind, payload = worker["connection"].recv()
                    except (EOFError, OSError):
                        yield from self._replace(worker, pending)
                        continue
                    if kind == "ready":
                        worker["ready"] = True
                    elif kind == "done":
                        worker["episode"] = None
                        yield payload
                    else:
                        raise SweepError(f"{self.sweep.source}: a worker could not start: {payload}")
        except BaseException:   # Ctrl-C or the consumer stopped: finished episodes are already kept
            self.terminate()
            raise
        finally:
            self.close()

    def _replace(self, worker: dict, pending: list) -> Generator[dict, None, None]:
        process = worker["process"]
        process.join(timeout=5)
        code = process.exitcode
        self.workers.remove(worker)
        worker["connection"].close()
        if worker["episode"] is None and not worker["ready"]:
            raise SweepError(f"{self.sweep.source}: a worker died while starting (exit code {code})")
        if worker["episode"] is not None:
            yield failed_record(worker["episode"], f"worker crashed ({_exit_reason(code)})", self.sweep.metric_names)
        if pending:
            self._start_worker()

    def terminate(self) -> None:
        """Stop every worker now, mid-episode if need be."""
        for worker in self.workers:
            worker["process"].terminate()
        for worker in self.workers:
            worker["process"].join()
            worker["connection"].close()
        self.workers = []

    def close(self) -> None:
        for worker in self.workers:
            try:
                worker["connection"].send(None)
            except (BrokenPipeError, OSError):
                pass
        for worker in self.workers:
            worker["process"].join(timeout=2)
            if worker["process"].is_alive():
                worker["process"].terminate()
                worker["process"].join()
            worker["connection"].close()
        self.workers = []


def _exit_reason(code: int | None) -> str:
    if code is None:
        return "no exit code"
    if code < 0:
        import signal

        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exit code {code}"


class RayPool:
    """The same episodes on Ray: one actor per CPU (or ``jobs``), each an ``EpisodeRunner``.

    ``address`` None or ``"local"`` starts a local Ray; ``"auto"`` joins the
    running cluster, else starts a local one; anything else is a cluster
    address for ``ray.init``. Files the sweep names must exist at the same
    paths on every node. An actor that dies fails the episode it was running
    and is replaced; the episode it had queued runs again elsewhere.

    While more episodes wait than there are actors, each actor has a second
    episode queued behind the one it runs, so it starts the next one at once
    instead of idling through the driver's round trip (and whatever the
    consumer does with the record); the last ones are handed out one at a
    time, to whichever actor is free first.
    """

    def __init__(self, sweep: Sweep, jobs: int | None, address: str | None):
        try:
            import ray
        except ImportError:
            raise MissingExtra("--ray", "ray", EXTRAS["ray"]) from None
        self.ray = ray
        self.sweep = sweep
        self.jobs = jobs
        self.address = address
        self.actors: list[dict] = []   # {"actor": handle, "queue": deque of (reference, episode), running first}

    def _init(self) -> None:
        ray = self.ray
        options = {"include_dashboard": False, "log_to_driver": False, "logging_level": "ERROR"}
        if self.address in (None, "local"):
            ray.init(num_cpus=self.jobs, **options)
        elif self.address == "auto":
            try:
                ray.init(address="auto", **options)
            except ConnectionError:
                ray.init(num_cpus=self.jobs, **options)
        else:
            ray.init(address=self.address, **options)

    def _submit(self, pending: list) -> None:
        """Queue pending episodes on the actors: two each while plenty wait, else one each."""
        for worker in self.actors:
            while pending and len(worker["queue"]) < (2 if len(pending) > len(self.actors) else 1):
                episode = pending.pop()
                worker["queue"].append((worker["actor"].run.remote(episode), episode))

    def run(self, episodes: Sequence[Episode]) -> Generator[dict, None, None]:
        ray = self.ray
        self._init()
        try:
            actor_class = ray.remote(num_cpus=1)(_RayEpisodeActor)
            count = self.jobs or max(1, int(ray.cluster_resources().get("CPU", 1)))
            pending = list(reversed(episodes))
            self.actors = [{"actor": actor_class.remote(self.sweep), "queue": deque()}
                           for _ in range(min(count, len(episodes)))]
            self._submit(pending)
            while any(worker["queue"] for worker in self.actors):
                # an actor runs its episodes in order, so only the first one of each can finish next
                running = {worker["queue"][0][0]: worker for worker in self.actors if worker["queue"]}
                done, _ = ray.wait(list(running), num_returns=1)
                worker = running[done[0]]
                _reference, episode = worker["queue"].popleft()
                try:
                    record = ray.get(done[0])
                except ray.exceptions.RayActorError as error:
                    record = failed_record(episode, f"worker crashed ({_first_line(error)})", self.sweep.metric_names)
                    pending.extend(queued for _reference, queued in reversed(worker["queue"]))
                    worker["actor"], worker["queue"] = actor_class.remote(self.sweep), deque()
                except ray.exceptions.RayTaskError as error:
                    record = failed_record(episode, f"worker error: {_first_line(error)}", self.sweep.metric_names)
                self._submit(pending)
                yield record
        finally:
            self.actors = []
            ray.shutdown()


def _first_line(error: BaseException) -> str:
    text = str(error).strip().splitlines()
    return text[0] if text else type(error).__name__


class _RayEpisodeActor:
    """A Ray actor around one ``EpisodeRunner`` (wrapped with ``ray.remote`` only when Ray is used)."""

    def __init__(self, sweep: Sweep):
        quiet_logging()
        self.runner = EpisodeRunner(sweep)

    def run(self, episode: Episode) -> dict:
        try:
            return self.runner.run(episode)
        except Exception as error:
            return failed_record(episode, f"worker error: {type(error).__name__}: {error}", self.runner.sweep.metric_names)
