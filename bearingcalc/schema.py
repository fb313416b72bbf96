"""JSON Schema (draft 2020-12) of the spec format, generated from the pydantic models.

Editors (the YAML language server) and tools such as check-jsonschema use it to
catch unknown keys and wrong types as a spec is typed; units and physics are
checked by ``bearingcalc check``.
"""

from __future__ import annotations

from typing import Annotated, Any, Union

from pydantic import Field, TypeAdapter

from bearingcalc.kinds import KINDS

DRAFT = "https://json-schema.org/draft/2020-12/schema"


def spec_schema(kind: str | None = None) -> dict[str, Any]:
    """The schema of one kind's spec, or of any spec (a union on ``kind``)."""
    if kind is not None:
        schema = KINDS[kind].model.model_json_schema()
        title = f"bearingcalc {kind} spec"
    else:
        models = tuple(k.model for k in KINDS.values())
        union = Annotated[Union[models], Field(discriminator="kind")]  # type: ignore[valid-type]  # noqa: UP007
        generated = TypeAdapter(union).json_schema()
        # Plain JSON Schema picks the branch: a validator that ignores OpenAPI's
        # discriminator would otherwise report a spec's errors against every branch.
        chosen = generated["discriminator"]["mapping"]
        schema = {"type": "object", "required": ["kind"],
                  "properties": {"kind": {"enum": list(chosen)}},
                  "allOf": [{"if": {"properties": {"kind": {"const": name}},
                                    "required": ["kind"]},
                             "then": {"$ref": reference}}
                            for name, reference in chosen.items()],
                  "$defs": generated["$defs"]}
        title = "bearingcalc spec"
    return {"$schema": DRAFT, "title": title,
            "description": "A bearingcalc design spec; see 'bearingcalc new --list'.", **schema}
