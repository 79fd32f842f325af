"""Elementwise helpers shared by the math, compare and boolean nodes.

Not a node type (no ``SPEC``; the leading underscore keeps the registry away).

Values are numbers, tuples of numbers (``double[3]``), arrays (tuples) of numbers
or of tuples (``double[3][]``). numpy arrays and scalars are accepted and turned
into plain Python values. Two operands combine elementwise when they have the
same shape; a lower-rank operand is broadcast over the higher-rank one (a scalar
over a tuple or array, a ``double[3]`` over a ``double[3][]``). Results are
plain Python numbers / tuples.
"""
from __future__ import annotations

import numbers
import operator


class MathError(ValueError):
    """An operand does not fit the operation; the message names the input."""


def plain(value):
    """numpy arrays / scalars and lists -> tuples of plain Python values."""
    if not isinstance(value, (str, bytes)) and hasattr(value, "tolist"):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return tuple(plain(item) for item in value)
    return value


def is_number(value) -> bool:
    cls = type(value)
    if cls is float or cls is int:   # the common case, without the slow ABC check below
        return True
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def is_boolean(value) -> bool:
    return isinstance(value, (bool, int)) and not isinstance(value, float)


# Exact types every value of which ``plain`` leaves unchanged and the keyed ``accept`` accepts:
# operands of these types take the fast path (a direct ``op`` call), with the same result.
_TRIVIAL = {is_number: frozenset((int, float)), is_boolean: frozenset((bool, int))}


def _rank(value) -> int:
    rank = 0
    while isinstance(value, tuple):
        rank += 1
        if not value:
            break
        value = value[0]
    return rank


def _describe(value) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def elementwise(op, operands, names, accept=is_number, kind="numbers"):
    """Apply ``op`` to the elements of ``operands`` (a list of values), broadcasting.

    ``names`` are the input names used in error messages; ``accept`` checks each
    scalar leaf (``kind`` says what was expected).
    """
    trivial = _TRIVIAL.get(accept)
    if trivial is not None:
        for value in operands:
            if type(value) not in trivial:
                break
        else:  # plain scalars only: nothing to convert, check or broadcast
            return op(*operands)
    values = [plain(v) for v in operands]

    def combine(items):
        tuples = [isinstance(item, tuple) for item in items]
        if not any(tuples):
            for name, item in zip(names, items):
                if not accept(item):
                    raise MathError(f"inputs:{name} must hold {kind}, got {_describe(item)}")
            return op(*items)
        ranks = [_rank(item) for item in items]
        top = max(ranks)
        length = None
        for name, item, rank in zip(names, items, ranks):
            if rank == top:
                if length is None:
                    length = len(item)
                elif len(item) != length:
                    raise MathError(
                        f"cannot combine {', '.join('inputs:' + n for n in names)}: "
                        f"lengths {length} and {len(item)} differ (inputs:{name})")
        return tuple(
            combine([item[i] if rank == top else item for item, rank in zip(items, ranks)])
            for i in range(length))

    return combine(values)


def require(db, name):
    """The value of input ``name``; MathError when it is unset (an unconnected ``any``)."""
    value = getattr(db.inputs, name)
    if value is None:
        raise MathError(f"inputs:{name} has no value; connect it or set a value")
    return value


def compute_binary(db, op, output, names=("a", "b"), accept=is_number, kind="numbers"):
    """Shared compute of the two-operand nodes: outputs.<output> = op(a, b) elementwise."""
    trivial = _TRIVIAL.get(accept)
    if trivial is not None and len(names) == 2:
        inputs = db.inputs
        a, b = getattr(inputs, names[0]), getattr(inputs, names[1])
        if type(a) in trivial and type(b) in trivial:  # plain scalars: what elementwise would do, minus the checks
            try:
                result = op(a, b)
            except MathError as error:
                db.error(str(error))
                return
            setattr(db.outputs, output, result)
            return
    try:
        result = elementwise(op, [require(db, n) for n in names], names, accept, kind)
    except MathError as error:
        db.error(str(error))
        return
    setattr(db.outputs, output, result)


def divide(a, b):
    if b == 0:
        raise MathError("division by zero: inputs:b is 0 (or has a zero element)")
    return a / b


COMPARISONS = {
    ">": operator.gt,
    "<": operator.lt,
    ">=": operator.ge,
    "<=": operator.le,
    "==": operator.eq,
    "!=": operator.ne,
}


def compute_unary(db, op, input_name, output, accept=is_number, kind="numbers"):
    """Shared compute of the one-operand nodes: outputs.<output> = op(input) elementwise."""
    try:
        result = elementwise(op, [require(db, input_name)], (input_name,), accept, kind)
    except (MathError, ValueError) as error:
        db.error(f"inputs:{input_name}: {error}")
        return
    setattr(db.outputs, output, result)


def zero_flags(db) -> tuple[bool, ...]:
    """AnyZero's and EachZero's test: one flag per element of inputs:value (one for a scalar), true where it is
    zero within inputs:tolerance; an element that is itself a tuple is zero when all its numbers are."""
    def zero(element) -> bool:
        if isinstance(element, tuple):
            return all(zero(item) for item in element)
        if not is_number(element):
            db.error(f"inputs:value must hold numbers, got {element!r}")
        return abs(element) <= db.inputs.tolerance

    value = plain(db.inputs.value)
    if value is None:
        db.error("inputs:value has no value; connect it or set a value")
    return tuple(zero(item) for item in value) if isinstance(value, tuple) else (zero(value),)
