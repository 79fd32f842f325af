"""The user's files, read and written safely.

Reading: only regular files (a folder or a device such as /dev/zero is refused
before anything is read), at most ``MAX_INPUT_BYTES``, strict UTF-8, and JSON
strictly as RFC 8259 says: no ``NaN``/``Infinity`` literals, no duplicate keys,
no number that overflows a double, no lone surrogate escapes, bounded nesting.
Every refusal is a ``FileProblem`` whose message is one line naming the file.

Writing: ``atomic_output`` writes into a temporary file (or folder) next to the
target and renames it into place only when the writer finished, so an error or
Ctrl-C never leaves a half-written file; an existing target is refused unless
``force``; the result gets the permissions the user's umask asks for
(``tempfile.mkstemp`` alone would leave 0600).
"""
from __future__ import annotations

import json
import math
import os
import re
import shutil
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Iterator

from graphflow.errors import BadInput, raise_if_interrupted

MAX_INPUT_BYTES = 256 * 1024 * 1024
MAX_JSON_DEPTH = 64      # graph documents nest about 5 levels; deeper input is an attack or a mistake


class FileProblem(BadInput):
    """A file that cannot be read or written as asked; the message is one line naming it."""

    def __init__(self, file, reason: str):
        self.file = str(file)
        self.reason = one_line(reason)
        super().__init__(f"{one_line(self.file)}: {self.reason}")


def _where(path) -> str:
    return one_line(str(path))


def one_line(text: str) -> str:
    """*text* with line breaks and other control characters escaped, so a message stays on one line."""
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() or c == " " else c.encode("unicode_escape").decode("ascii") for c in text)


# ---------------------------------------------------------------- reading

def read_text(path) -> str:
    """A regular file's text (UTF-8); FileProblem for anything else."""
    target = Path(path)
    try:
        if not target.exists():
            raise FileProblem(path, "file not found")
        if target.is_dir():
            raise FileProblem(path, "is a folder, not a file")
        if not target.is_file():
            raise FileProblem(path, "not a regular file (a device, pipe or socket)")
        with open(target, "rb") as stream:
            data = stream.read(MAX_INPUT_BYTES + 1)
    except OSError as error:
        raise FileProblem(path, f"cannot read file: {error.strerror or error}") from None
    if len(data) > MAX_INPUT_BYTES:
        raise FileProblem(path, f"larger than {MAX_INPUT_BYTES // (1024 * 1024)} MB; not read")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data.count(b"\n", 0, error.start) + 1
        raise FileProblem(path, f"not UTF-8 text (byte 0x{data[error.start]:02x} on line {line})") from None


class _StrictJSONError(ValueError):
    pass


def _reject_constant(name: str):
    raise _StrictJSONError(f"{name} is not a JSON value (RFC 8259 has no NaN or Infinity)")


def _finite_float(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise _StrictJSONError(f"number {text[:40]} is too large (beyond the double range)")
    return value


def _checked_int(text: str) -> int:
    if len(text.lstrip("-")) > 400:
        raise _StrictJSONError(f"integer with {len(text)} digits is too large")
    return int(text)


def _unique_keys(pairs: list[tuple[str, Any]]) -> dict:
    result = {}
    for key, value in pairs:
        if key in result:
            raise _StrictJSONError(f"duplicate key {json.dumps(key, ensure_ascii=True)} in one object")
        result[key] = value
    return result


def loads_strict(text: str, source: str, *, non_finite: bool = False) -> Any:
    """Parse JSON as RFC 8259 says; FileProblem naming *source* (and the line, or the key) otherwise.

    *non_finite*: also read ``NaN``, ``Infinity`` and ``-Infinity`` (what graphflow's own traces write for
    non-finite floats, as Python's json does); user files never hold them."""
    try:
        data = json.loads(text, object_pairs_hook=_unique_keys, parse_constant=float if non_finite else _reject_constant,
                          parse_float=_finite_float, parse_int=_checked_int)
    except json.JSONDecodeError as error:
        raise FileProblem(source, f"malformed JSON at line {error.lineno} column {error.colno}: {error.msg}") from None
    except (_StrictJSONError, RecursionError):
        problem = _locate_problem(text)
        if problem is None:      # the scanner below agrees with json on what is wrong; this is a safety net
            raise FileProblem(source, "invalid JSON") from None
        raise FileProblem(source, problem) from None
    try:
        _check_tree(data, source)
    except FileProblem:
        raise FileProblem(source, _locate_problem(text) or "invalid JSON") from None
    return data


_NUMBER = re.compile(r"(-?(?:0|[1-9]\d*))(\.\d+)?([eE][-+]?\d+)?")
_WHITESPACE = re.compile(r"[ \t\n\r]*")
_LITERALS = (("true", True), ("false", False), ("null", None), ("NaN", "NaN"), ("Infinity", "Infinity"),
             ("-Infinity", "-Infinity"))


def _locate_problem(text: str) -> str | None:
    """Where strict parsing failed and why: "invalid JSON at line L column C (key/path, node 'n'): reason".

    A second, iterative pass over text that ``json`` already tokenised: it keeps the key path and
    finds the first NaN/Infinity literal, duplicate key, overflowing number, lone surrogate or
    too-deep nesting. Only called on a refusal, so it costs nothing on a good file.
    """
    path: list = []          # keys and indices down to the current value
    frames: list = []        # per open container: [kind, keys seen, next key or index]
    position = 0
    expecting_key = False

    def found(at: int, reason: str) -> str:
        line = text.count("\n", 0, at) + 1
        column = at - (text.rfind("\n", 0, at) + 1) + 1
        where = "/".join(str(part) for part in path[:12]) + ("/..." if len(path) > 12 else "")
        node = _node_name(text, path)
        label = ", ".join(part for part in (where, f"node '{node}'" if node else "") if part)
        return f"invalid JSON at line {line} column {column}" + (f" ({label})" if label else "") + f": {reason}"

    while True:
        blank = _WHITESPACE.match(text, position)
        position = blank.end() if blank is not None else position
        if position >= len(text):
            return None
        char = text[position]
        if char in ",:":
            position += 1
            if char == "," and frames and frames[-1][0] == "array":
                frames[-1][2] += 1
                path[-1] = frames[-1][2]
            expecting_key = char == "," and bool(frames) and frames[-1][0] == "object"
            continue
        if char in "}]":
            frames.pop()
            path.pop()
            position += 1
            continue
        if char == '"':
            value, end = json.decoder.scanstring(text, position + 1)  # type: ignore[attr-defined]  # not in typeshed
            if not _encodes(value):
                shown = value.encode("utf-8", "backslashreplace").decode("ascii", "backslashreplace")[:60]
                return found(position, f"lone surrogate escape in the string \"{shown}\"")
            if expecting_key:
                keys = frames[-1][1]
                path[-1] = value
                if value in keys:
                    return found(position, f"duplicate key {json.dumps(value, ensure_ascii=True)} in one object")
                keys.add(value)
                expecting_key = False
            position = end
            continue
        if char in "{[":
            if len(frames) >= MAX_JSON_DEPTH:
                return found(position, f"nested more than {MAX_JSON_DEPTH} levels deep")
            frames.append(["object" if char == "{" else "array", set(), 0])
            path.append(None if char == "{" else 0)
            expecting_key = char == "{"
            position += 1
            continue
        for literal, value in _LITERALS:
            if text.startswith(literal, position):
                if isinstance(value, str):
                    return found(position, f"{literal} is not a JSON value (RFC 8259 has no NaN or Infinity)")
                position += len(literal)
                break
        else:
            number = _NUMBER.match(text, position)
            if number is None:
                return None
            whole = number.group(0)
            if number.group(2) or number.group(3):
                if not math.isfinite(float(whole)):
                    return found(position, f"number {whole[:40]} is too large (beyond the double range)")
            elif len(whole.lstrip("-")) > 400:
                return found(position, f"integer with {len(whole)} digits is too large")
            position = number.end()


def _encodes(text: str) -> bool:
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


def _node_name(text: str, path: list) -> str | None:
    """The ``name`` of graph node ``nodes[i]`` when *path* is inside one (read leniently: the file has a flaw)."""
    if len(path) < 2 or path[0] != "nodes" or not isinstance(path[1], int):
        return None
    try:
        nodes = json.loads(text).get("nodes")
        name = nodes[path[1]].get("name")
    except (ValueError, RecursionError, AttributeError, IndexError, TypeError):
        return None
    return one_line(name) if isinstance(name, str) else None


def _check_tree(data: Any, source: str) -> None:
    """Bounded nesting and no lone surrogates (they cannot be printed or written as UTF-8)."""
    pending = [(data, 1)]
    while pending:
        value, depth = pending.pop()
        if isinstance(value, str):
            _check_string(value, source)
        elif isinstance(value, (list, dict)):
            if depth > MAX_JSON_DEPTH:
                raise FileProblem(source, f"invalid JSON: nested more than {MAX_JSON_DEPTH} levels deep")
            if isinstance(value, dict):
                for key, item in value.items():
                    _check_string(key, source)
                    pending.append((item, depth + 1))
            else:
                pending.extend((item, depth + 1) for item in value)


def _check_string(text: str, source: str) -> None:
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        shown = text.encode("utf-8", "backslashreplace").decode("ascii", "backslashreplace")[:60]
        raise FileProblem(source, f"invalid JSON: lone surrogate escape in the string \"{shown}\"") from None


def read_json(path) -> Any:
    """``read_text`` + ``loads_strict``."""
    return loads_strict(read_text(path), str(path))


# ---------------------------------------------------------------- writing

def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def refuse_existing(target, force: bool, *, folder: bool = False) -> None:
    """FileProblem when writing *target* would overwrite something without *force*, or its folder is missing.

    A folder target (video frames) may exist if it is empty.
    """
    path = Path(target)
    if folder:
        if path.exists() and not path.is_dir():
            raise FileProblem(target, "exists and is not a folder; not overwriting it")
        if path.is_dir() and any(path.iterdir()) and not force:
            raise FileProblem(target, "folder already holds files; not overwriting them (use --force)")
    else:
        if path.is_dir():
            raise FileProblem(target, "is a folder, not a file")
        if path.exists() and not force:
            raise FileProblem(target, "already exists; not overwriting it (use --force)")
    parent = path.parent if str(path.parent) else Path(".")
    if not parent.is_dir():
        raise FileProblem(target, f"folder {_where(parent)} does not exist")


@contextmanager
def atomic_output(target, *, force: bool = False, folder: bool = False) -> Iterator[Path]:
    """Yield a temporary path next to *target* to write into; on success it replaces *target*.

    ``folder=True`` yields a temporary folder whose files are moved into the
    target folder (created if missing). On any exception, KeyboardInterrupt
    included, the temporary file or folder is removed and *target* is untouched.
    """
    refuse_existing(target, force, folder=folder)
    path = Path(target)
    parent = path.parent if str(path.parent) else Path(".")
    try:
        if folder:
            temporary = Path(tempfile.mkdtemp(prefix=f".{path.name}.", suffix=".tmp", dir=parent))
        else:
            handle, name = tempfile.mkstemp(prefix=f".{path.name}.", suffix=f".tmp{path.suffix}", dir=parent)
            os.close(handle)
            temporary = Path(name)
    except OSError as error:
        raise FileProblem(target, f"cannot write: {error.strerror or error}") from None
    try:
        yield temporary
        raise_if_interrupted()   # a Ctrl-C that the writer's code swallowed: no output, as for any other
        mask = _umask()
        if folder:
            _commit_folder(temporary, path, mask)
        else:
            if not force and path.exists():
                raise FileProblem(target, "appeared while writing; not overwriting it (use --force)")
            os.chmod(temporary, 0o666 & ~mask)
            os.replace(temporary, path)
    except BaseException:
        if folder:
            shutil.rmtree(temporary, ignore_errors=True)
        elif temporary.exists():
            temporary.unlink()
        raise


def _commit_folder(temporary: Path, target: Path, mask: int) -> None:
    for item in temporary.iterdir():
        os.chmod(item, 0o666 & ~mask)
    if not target.exists():
        os.chmod(temporary, 0o777 & ~mask)
        os.replace(temporary, target)
        return
    for item in sorted(temporary.iterdir()):
        os.replace(item, target / item.name)
    temporary.rmdir()


def write_text(target, text: str, *, force: bool = False) -> None:
    """Write *text* (UTF-8) atomically to *target*; see ``atomic_output``."""
    with atomic_output(target, force=force) as temporary:
        with open(temporary, "w", encoding="utf-8", newline="\n") as stream:
            stream.write(text)
            stream.flush()
            os.fsync(stream.fileno())


def write_bytes(target, data: bytes, *, force: bool = False) -> None:
    """Write *data* atomically to *target*; see ``atomic_output``."""
    with atomic_output(target, force=force) as temporary:
        temporary.write_bytes(data)
