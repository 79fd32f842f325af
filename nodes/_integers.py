"""Conversions to Kit's integer types, shared by the To<Int> nodes.

Not a node type (no ``SPEC``). Kit's reference: floating-point values are
truncated towards zero; a negative value converted to an unsigned type is 2^bits
minus its magnitude. graphflow wraps every out-of-range integer the same way
(two's complement for the signed types), so a conversion never fails on a value.
"""
from __future__ import annotations

import math

from graphflow_nodes._math import MathError, elementwise, is_boolean, is_number


def wrap(value, bits: int, signed: bool) -> int:
    """*value* (bool or number) truncated towards zero and wrapped to a *bits*-wide integer."""
    if isinstance(value, float) and not math.isfinite(value):
        raise MathError(f"inputs:value {value!r} has no integer value")
    number = int(value) % (1 << bits)
    if signed and number >= 1 << (bits - 1):
        number -= 1 << bits
    return number


def compute_integer(db, bits: int, signed: bool, tuples: bool) -> None:
    """outputs:converted = inputs:value as integers; *tuples*: tuple shapes kept (else arrays only)."""
    value = db.inputs.value
    if value is None:
        db.error("inputs:value has no value; connect it or set a value")
    if not tuples and isinstance(value, tuple) and value and isinstance(value[0], tuple):
        db.error(f"inputs:value must be a scalar or an array of scalars for {bits}-bit conversion, got tuples")
    try:
        db.outputs.converted = elementwise(lambda x: wrap(x, bits, signed), [value], ("value",),
                                           lambda x: is_boolean(x) or is_number(x), "bools or numbers")
    except MathError as error:
        db.error(str(error))
