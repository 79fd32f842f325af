"""Kit attribute bundles as graphflow values: small, frozen, ordered.

A bundle is what Kit's bundle ports carry: named, typed attributes (a prim's
attributes when a ReadPrims node made it) and child bundles (ReadPrims makes
one child per prim). Kit marks the prim a bundle was read from with two token
attributes, ``sourcePrimPath`` and ``sourcePrimType``; here they are ordinary
attributes too, so GetAttributeNames lists them as Kit does.

Bundles are immutable: a node that "changes" one (InsertAttribute,
RenameAttribute, ...) outputs a new bundle, so a value can flow along
several connections without copies.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Iterator

SOURCE_PRIM_PATH = "sourcePrimPath"
SOURCE_PRIM_TYPE = "sourcePrimType"
PRIM_INTERNAL = (SOURCE_PRIM_PATH, SOURCE_PRIM_TYPE)   # what RemoveAttribute keeps unless told otherwise
WORLD_MATRIX = "worldMatrix"
BOUNDING_BOX = ("bboxMinCorner", "bboxMaxCorner", "bboxTransform")
DERIVED = (WORLD_MATRIX, *BOUNDING_BOX)      # computed by a prim reader, not attributes of the prim


@dataclass(frozen=True)
class BundleAttribute:
    """One attribute of a bundle: its name, graphflow type name (``double[3]``, ``token[]``) and value."""

    name: str
    type: str
    value: Any


@dataclass(frozen=True)
class Bundle:
    """An ordered set of typed attributes plus child bundles; equality is by content."""

    attributes: tuple[BundleAttribute, ...] = ()
    children: tuple[Bundle, ...] = ()

    @staticmethod
    def of_prim(path: str, prim_type: str, attributes: tuple[BundleAttribute, ...]) -> Bundle:
        """A prim's bundle as Kit's readers make it: sourcePrimPath and sourcePrimType, then the attributes."""
        marks = (BundleAttribute(SOURCE_PRIM_PATH, "token", path), BundleAttribute(SOURCE_PRIM_TYPE, "token", prim_type))
        return Bundle(marks + tuple(a for a in attributes if a.name not in PRIM_INTERNAL))

    def __iter__(self) -> Iterator[BundleAttribute]:
        return iter(self.attributes)

    def __len__(self) -> int:
        return len(self.attributes)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(attribute.name for attribute in self.attributes)

    def get(self, name: str) -> BundleAttribute | None:
        for attribute in self.attributes:
            if attribute.name == name:
                return attribute
        return None

    @property
    def source_prim_path(self) -> str:
        found = self.get(SOURCE_PRIM_PATH)
        return str(found.value) if found is not None else ""

    @property
    def source_prim_type(self) -> str:
        found = self.get(SOURCE_PRIM_TYPE)
        return str(found.value) if found is not None else ""

    def with_attribute(self, attribute: BundleAttribute) -> Bundle:
        """This bundle with *attribute* added, or replacing the one of the same name in place."""
        if self.get(attribute.name) is None:
            return Bundle(self.attributes + (attribute,), self.children)
        return Bundle(tuple(attribute if a.name == attribute.name else a for a in self.attributes), self.children)

    def without(self, names) -> Bundle:
        names = set(names)
        return Bundle(tuple(a for a in self.attributes if a.name not in names), self.children)

    def renamed(self, renames: dict[str, str]) -> Bundle:
        """Attributes renamed old -> new; a renamed attribute replaces one already holding the new name."""
        result = Bundle((), self.children)
        for attribute in self.attributes:
            result = result.with_attribute(BundleAttribute(renames.get(attribute.name, attribute.name),
                                                           attribute.type, attribute.value))
        return result

    def with_children(self, children: tuple[Bundle, ...]) -> Bundle:
        return Bundle(self.attributes, tuple(children))


def type_of_value(value: Any) -> str | None:
    """The graphflow type a plain value holds, for attributes inserted from ``any`` ports; None if none fits.

    Booleans are ``bool``, integers ``int64``, floats ``double``, strings ``token``; a tuple of 2, 3, 4, 9
    or 16 numbers is a ``double[N]`` (``int[N]`` when all are integers); a tuple of those an array.
    """
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int64"
    if isinstance(value, float):
        return "double"
    if isinstance(value, str):
        return "token"
    if isinstance(value, Bundle):
        return None
    if isinstance(value, tuple):
        if value and all(isinstance(item, (int, float)) and not isinstance(item, bool) for item in value):
            if len(value) in (2, 3, 4, 9, 16):
                return f"{'int' if all(isinstance(item, int) for item in value) else 'double'}[{len(value)}]"
        if not value:
            return "double[]"
        element = type_of_value(value[0])
        if element and not element.endswith("[]") and all(type_of_value(item) == element for item in value):
            return element + "[]"
    return None
