"""Run-time edits of a world's USD stage: variant selections, relationship targets, material bindings, values.

Kit's variant, relationship and material nodes edit the open stage while a graph
runs. A graphflow world composes its physics once, when it is built, so an edit
here is allowed only when it leaves what is simulated as it was: before and
after each edit the physics under the edited prim is read (UsdPhysics' own
parser: bodies, colliders with their sizes and physics materials, joints and
their bodies, articulations, all with their transforms; plus every authored
``physics:``/``physx``/``drive:``/``limit:`` property). When they differ the
edit is rolled back and refused with one line naming the prim and what would
change. Edits go to one anonymous layer under the stage's session layer, never
to a file on disk; ``discard()`` (a world reset) empties it, so a second run or
a sweep's next episode starts from the file's state.

``StageEditing`` gives a world the ``graphflow.world.World`` methods of this
family on its ``stage``; ``PyBulletWorld`` and ``FakeWorld`` use it.
"""
from __future__ import annotations

import warnings
from typing import Any, Callable, Iterable, Mapping, NamedTuple

from graphflow.world import WorldError

PHYSICS_PREFIXES = ("physics:", "physx", "drive:", "limit:", "isaac")     # "isaac": surface grippers
EDIT_LAYER_TAG = "graphflow-stage-edits"


class VariantValue(NamedTuple):
    """One attribute a variant authors: its USD type name (``double3``, ``token``, ``quatf``) and plain value."""

    type_name: str
    value: Any


def plain(value):
    """A USD value as plain Python: vectors and arrays as tuples, quaternions as (x, y, z, w), matrices as rows."""
    if hasattr(value, "GetImaginary") and hasattr(value, "GetReal"):
        imaginary = value.GetImaginary()
        return (float(imaginary[0]), float(imaginary[1]), float(imaginary[2]), float(value.GetReal()))
    if isinstance(value, (bool, int, float, str)):
        return value
    if hasattr(value, "__len__"):
        return tuple(plain(v) for v in value)
    return str(value) if value is not None else None


def usd_value(attribute, value):
    """*value* (plain Python) as the attribute's USD type (an array element by element)."""
    type_name = attribute.GetTypeName()
    if type_name.isArray:
        element = type_name.scalarType
        return type_name.type.pythonClass([_usd_scalar(element.type.pythonClass, item) for item in value])
    return _usd_scalar(type_name.type.pythonClass, value)


def _usd_scalar(python_type, value):
    from pxr import Gf

    if python_type in (Gf.Quatd, Gf.Quatf, Gf.Quath):
        x, y, z, w = value
        return python_type(w, x, y, z)
    if python_type is not None and isinstance(value, tuple):
        return python_type(value) if hasattr(python_type, "GetRow") else python_type(*value)
    return value


# -- what is simulated under a prim ------------------------------------------------------------------

def physics_state(stage, root: str) -> dict[str, str]:
    """Everything the physics import reads under *root*, as comparable text keyed by what it is."""
    from pxr import Usd, UsdPhysics

    parse = getattr(UsdPhysics, "UsdPhysicsLoadStageFromPrimRange", None) or UsdPhysics.LoadUsdPhysicsFromRange
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        parsed = parse(stage, [root])
    state: dict[str, str] = {}
    for kind, (paths, descs) in parsed.items():
        kind_name = str(kind).rsplit(".", 1)[-1]
        for path, desc in zip(paths, descs):
            for field in dir(desc):
                if not field.startswith("_") and field != "isValid":
                    state[f"{kind_name} {path} {field}"] = described(getattr(desc, field))
    prim = stage.GetPrimAtPath(root)
    for each in Usd.PrimRange(prim, Usd.TraverseInstanceProxies()) if prim else ():
        for attribute in each.GetAuthoredAttributes():
            if attribute.GetName().startswith(PHYSICS_PREFIXES):
                state[f"{attribute.GetPath()}"] = repr(attribute.Get())
        for relationship in each.GetAuthoredRelationships():
            if relationship.GetName().startswith(PHYSICS_PREFIXES):
                state[f"{relationship.GetPath()}"] = repr(relationship.GetTargets())
    return state


def described(value, depth: int = 0) -> str:
    """A parser value as text that compares by content: the parser's structs and vectors (joint drives,
    limits) have no repr of their own, so they are spelled out field by field."""
    text = repr(value)
    if " object at 0x" not in text or depth > 4:
        return text
    try:
        items = list(value)
    except TypeError:
        fields = [name for name in dir(value) if not name.startswith("_") and not callable(getattr(value, name))]
        return "{" + ", ".join(f"{name}: {described(getattr(value, name), depth + 1)}" for name in fields) + "}"
    return "[" + ", ".join(described(item, depth + 1) for item in items) + "]"


def first_change(before: Mapping[str, str], after: Mapping[str, str]) -> str | None:
    """The first difference between two ``physics_state``s, in words; None when they are equal."""
    for key in sorted(set(before) | set(after)):
        old, new = before.get(key), after.get(key)
        if old != new:
            if old is None:
                return f"{key} would appear ({new})"
            if new is None:
                return f"{key} would disappear (was {old})"
            return f"{key} would change from {old} to {new}"
    return None


# -- variants -----------------------------------------------------------------------------------------

def variant_opinions(prim, variant_set: str, variant: str) -> tuple[dict[str, VariantValue], dict[str, tuple]]:
    """What *variant* of *variant_set* authors under *prim*: attribute values by stage attribute path, and
    material-binding relationship targets by stage relationship path (strongest layer first)."""
    from pxr import Sdf

    values: dict[str, VariantValue] = {}
    bindings: dict[str, tuple] = {}
    for spec in prim.GetPrimStack():
        variant_sets = spec.variantSets
        if variant_set not in variant_sets or variant not in variant_sets[variant_set].variants:
            continue
        origin = spec.path.StripAllVariantSelections()
        pending = [variant_sets[variant_set].variants[variant].primSpec]
        while pending:
            prim_spec = pending.pop()
            for attribute in prim_spec.attributes:
                if attribute.HasDefaultValue():
                    path = str(attribute.path.StripAllVariantSelections().ReplacePrefix(origin, prim.GetPath()))
                    values.setdefault(path, VariantValue(str(attribute.typeName), plain(attribute.default)))
            for relationship in prim_spec.relationships:
                if relationship.name.startswith("material:binding"):
                    path = str(relationship.path.StripAllVariantSelections().ReplacePrefix(origin, prim.GetPath()))
                    targets = relationship.targetPathList.GetAddedOrExplicitItems()
                    bindings.setdefault(path, tuple(str(Sdf.Path(t)) for t in targets))
            pending.extend(prim_spec.nameChildren)
    return values, bindings


class StageEdits:
    """One world's edits of its stage: an anonymous layer under the session layer, checked against physics."""

    def __init__(self, stage):
        self.stage = stage
        self.layer = None

    def edit(self, root: str, what: str, change: Callable[[], None]) -> None:
        """Run *change* with the edit layer as edit target; undo it and raise when the physics under *root*
        would change."""
        from pxr import Sdf, Tf, Usd

        if self.layer is None:
            self.layer = Sdf.Layer.CreateAnonymous(EDIT_LAYER_TAG)
        session = self.stage.GetSessionLayer()
        if self.layer.identifier not in session.subLayerPaths:      # a sweep cleared the session layer since
            session.subLayerPaths.insert(0, self.layer.identifier)
        backup = Sdf.Layer.CreateAnonymous(EDIT_LAYER_TAG)
        backup.TransferContent(self.layer)
        before = physics_state(self.stage, root)
        try:
            with Usd.EditContext(self.stage, self.layer):
                change()
        except WorldError:
            self.layer.TransferContent(backup)
            raise
        except Tf.ErrorException as error:            # USD refused the authoring (an instance proxy, a bad value)
            self.layer.TransferContent(backup)
            reason = str(error).strip().splitlines()[-1].split(" : ", 1)[-1].strip(" '")
            raise WorldError(f"{root}: {what} was refused by USD: {reason}") from None
        change_found = first_change(before, physics_state(self.stage, root))
        if change_found is not None:
            self.layer.TransferContent(backup)
            raise WorldError(f"{root}: {what} would change what is simulated ({change_found}), which is "
                             "composed once, at load")

    def discard(self) -> bool:
        """Drop every edit (a world reset); True when there were some."""
        if self.layer is None or self.layer.empty:
            return False
        self.layer.Clear()
        return True


class StageEditing:
    """The stage-editing methods of ``graphflow.world.World`` for a world with a ``stage`` attribute.

    A world calls ``discard_stage_edits()`` from its ``reset()``; ``stage_edited()`` is called after every
    accepted edit so the world can drop what it cached from the stage (a no-op here).
    """

    stage: Any
    stage_edits: StageEdits | None = None

    def stage_edited(self) -> None:
        """Hook: an edit was made; forget values read from the stage before it."""

    def discard_stage_edits(self) -> None:
        if self.stage_edits is not None and self.stage_edits.discard():
            self.stage_edited()

    def _stage_prim(self, prim_path: str):
        if self.stage is None:
            raise WorldError("this graph names no stage, so there are no prims to read or edit")
        prim = self.stage.GetPrimAtPath(prim_path) if prim_path.startswith("/") else None
        if not prim:
            raise WorldError(f"no prim {prim_path!r} on this stage")
        return prim

    def _apply_stage_edit(self, root: str, what: str, change: Callable[[], None]) -> None:
        self._stage_prim(root)
        if self.stage_edits is None:
            self.stage_edits = StageEdits(self.stage)
        self.stage_edits.edit(root, what, change)
        self.stage_edited()

    def _stage_variant_set(self, prim_path: str, variant_set: str):
        prim = self._stage_prim(prim_path)
        if not variant_set or not prim.GetVariantSets().HasVariantSet(variant_set):
            raise WorldError(f"{prim_path} has no variant set {variant_set!r}")
        return prim.GetVariantSets().GetVariantSet(variant_set)

    # variants
    def variant_sets(self, prim_path: str) -> tuple[str, ...]:
        return tuple(self._stage_prim(prim_path).GetVariantSets().GetNames())

    def variant_names(self, prim_path: str, variant_set: str) -> tuple[str, ...]:
        return tuple(self._stage_variant_set(prim_path, variant_set).GetVariantNames())

    def variant_selection(self, prim_path: str, variant_set: str) -> str:
        return self._stage_variant_set(prim_path, variant_set).GetVariantSelection()

    def set_variant_selection(self, prim_path: str, variant_set: str, variant: str) -> None:
        chosen = self._stage_variant_set(prim_path, variant_set)
        if variant and not chosen.HasAuthoredVariant(variant):
            raise WorldError(f"{prim_path}: variant set {variant_set!r} has no variant {variant!r} "
                             f"(it has {', '.join(chosen.GetVariantNames()) or 'none'})")

        def change():
            if variant:
                chosen.SetVariantSelection(variant)
            else:
                chosen.BlockVariantSelection()
            if chosen.GetVariantSelection() != variant:
                raise WorldError(f"{prim_path}: a stronger opinion on the session layer keeps variant set "
                                 f"{variant_set!r} at {chosen.GetVariantSelection()!r}")

        what = f"selecting variant {variant!r} of {variant_set!r}" if variant else f"clearing variant set {variant_set!r}"
        self._apply_stage_edit(prim_path, what, change)

    def variant_values(self, prim_path: str, variant_set: str, variant: str) -> dict[str, VariantValue]:
        """The attribute values *variant* authors under the prim, by attribute path (strongest layer's)."""
        chosen = self._stage_variant_set(prim_path, variant_set)
        if not chosen.HasAuthoredVariant(variant):
            raise WorldError(f"{prim_path}: variant set {variant_set!r} has no variant {variant!r} "
                             f"(it has {', '.join(chosen.GetVariantNames()) or 'none'})")
        return variant_opinions(self._stage_prim(prim_path), variant_set, variant)[0]

    def variant_bindings(self, prim_path: str, variant_set: str, variant: str) -> dict[str, tuple[str, ...]]:
        """The material-binding relationships *variant* authors under the prim: targets by relationship path."""
        self.variant_values(prim_path, variant_set, variant)
        return variant_opinions(self._stage_prim(prim_path), variant_set, variant)[1]

    def write_stage_values(self, prim_path: str, values: Mapping[str, Any], what: str = "writing values") -> None:
        """Author attribute values (plain Python, by attribute path under the prim) as run-time opinions; a
        ``VariantValue`` also creates its attribute, with its type, where the stage has none."""
        from pxr import Sdf

        stage = self._stage_prim(prim_path).GetStage()
        created = {path: value.type_name for path, value in values.items()
                   if isinstance(value, VariantValue) and not stage.GetAttributeAtPath(path)}
        attributes = [(path, value.value if isinstance(value, VariantValue) else value) for path, value in values.items()]
        for path in set(values) - set(created):
            self._stage_attribute(prim_path, path)
        for path in created:
            if not stage.GetPrimAtPath(path.rsplit(".", 1)[0]):
                raise WorldError(f"{prim_path}: {path} is on a prim this stage does not have now (a variant that "
                                 "is not selected defines it): select the variant to bring the prim in")

        def change():
            for path, value in attributes:
                attribute = stage.GetAttributeAtPath(path)
                if path in created:
                    owner, name = path.rsplit(".", 1)
                    attribute = stage.GetPrimAtPath(owner).CreateAttribute(name, Sdf.ValueTypeNames.Find(created[path]))
                try:
                    attribute.Set(usd_value(attribute, value))
                except Exception as error:      # pxr raises Tf errors of its own classes
                    raise WorldError(f"{attribute.GetPath()}: cannot take {value!r}: {error}") from None

        self._apply_stage_edit(prim_path, what, change)

    def clear_stage_values(self, prim_path: str, attribute_paths: Iterable[str], what: str = "clearing values") -> None:
        """Remove the run-time opinions on these attributes (the file's values show again); an attribute the
        stage does not have holds none."""
        stage = self._stage_prim(prim_path).GetStage()
        attributes = [attribute for path in attribute_paths if (attribute := stage.GetAttributeAtPath(path))]

        def change():
            for attribute in attributes:
                attribute.Clear()

        self._apply_stage_edit(prim_path, what, change)

    def _stage_attribute(self, prim_path: str, attribute_path: str):
        attribute = self._stage_prim(prim_path).GetStage().GetAttributeAtPath(attribute_path)
        if not attribute:
            raise WorldError(f"{prim_path}: no attribute {attribute_path} on this stage")
        return attribute

    # relationships
    def relationship_targets(self, prim_path: str, name: str) -> tuple[str, ...]:
        relationship = self._stage_prim(prim_path).GetRelationship(name) if name else None
        if not relationship:
            raise WorldError(f"{prim_path} has no relationship {name!r}")
        return tuple(str(target) for target in relationship.GetTargets())

    def set_relationship_targets(self, prim_path: str, name: str, targets: Iterable[str]) -> None:
        """Make the relationship (created when missing) target exactly *targets*."""
        from pxr import Sdf

        if not name:
            raise WorldError(f"{prim_path}: no relationship name given")
        paths = [Sdf.Path(target) for target in targets]
        prim = self._stage_prim(prim_path)

        def change():
            relationship = prim.GetRelationship(name) or prim.CreateRelationship(name, custom=True)
            relationship.SetTargets(paths)

        self._apply_stage_edit(prim_path, f"setting relationship {name} to {[str(p) for p in paths]}", change)

    # materials
    def bound_material(self, prim_path: str) -> str:
        """The material bound directly to the prim for all purposes, '' when none."""
        from pxr import UsdShade

        binding = UsdShade.MaterialBindingAPI(self._stage_prim(prim_path)).GetDirectBinding()
        return str(binding.GetMaterialPath()) if binding.GetMaterialPath() else ""

    def bind_material(self, prim_path: str, material_path: str) -> None:
        """Bind *material_path* to the prim directly, for all purposes."""
        from pxr import UsdShade

        material = UsdShade.Material(self._stage_prim(material_path))
        if not material:
            raise WorldError(f"{material_path} is not a Material prim")
        prim = self._stage_prim(prim_path)
        self._apply_stage_edit(prim_path, f"binding material {material_path}",
                   lambda: UsdShade.MaterialBindingAPI.Apply(prim).Bind(material))
