"""A small JSON Schema validator (draft 2020-12, the keywords docs/schemas/ use), standard
library only: ``errors(schema, value)`` lists where ``value`` breaks ``schema``.

A keyword it does not know is an error of the schema (``UnknownKeyword``), so a schema
never passes by using a keyword nothing checks."""

from __future__ import annotations

import re

ANNOTATIONS = {"$schema", "$id", "$defs", "title", "description", "$comment", "default",
               "examples"}
KNOWN = ANNOTATIONS | {"$ref", "type", "enum", "const", "properties", "required",
                       "additionalProperties", "patternProperties", "items", "prefixItems",
                       "minItems", "maxItems", "minimum", "maximum", "minLength", "pattern",
                       "anyOf", "oneOf", "allOf", "not"}


class UnknownKeyword(ValueError):
    pass


def _is(kind: str, value) -> bool:
    if kind == "null":
        return value is None
    if kind == "boolean":
        return isinstance(value, bool)
    if kind == "integer":
        return isinstance(value, int) and not isinstance(value, bool)
    if kind == "number":
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    if kind == "string":
        return isinstance(value, str)
    if kind == "array":
        return isinstance(value, list)
    if kind == "object":
        return isinstance(value, dict)
    raise UnknownKeyword(f"type {kind!r}")


def _same(a, b) -> bool:
    """JSON equality (1 and True differ)."""
    return type(a) is type(b) and a == b if isinstance(a, bool) or isinstance(b, bool) \
        else a == b


def errors(schema, value, root=None, where: str = "$") -> list[str]:
    root = schema if root is None else root
    if schema is True or schema == {}:
        return []
    if schema is False:
        return [f"{where}: nothing is allowed here"]
    unknown = set(schema) - KNOWN
    if unknown:
        raise UnknownKeyword(f"{where}: {sorted(unknown)}")
    out: list[str] = []
    if "$ref" in schema:
        ref = schema["$ref"]
        if not ref.startswith("#/"):
            raise UnknownKeyword(f"only local references: {ref}")
        target = root
        for part in ref[2:].split("/"):
            target = target[part]
        out += errors(target, value, root, where)
    if "type" in schema:
        kinds = schema["type"] if isinstance(schema["type"], list) else [schema["type"]]
        if not any(_is(k, value) for k in kinds):
            return out + [f"{where}: {value!r:.60} is not {' or '.join(kinds)}"]
    if "enum" in schema and not any(_same(value, e) for e in schema["enum"]):
        out.append(f"{where}: {value!r:.60} not one of {schema['enum']}")
    if "const" in schema and not _same(value, schema["const"]):
        out.append(f"{where}: {value!r:.60} is not {schema['const']!r}")
    if isinstance(value, dict):
        props = schema.get("properties", {})
        for key in schema.get("required", []):
            if key not in value:
                out.append(f"{where}: no key {key!r}")
        for key, item in value.items():
            matched = False
            if key in props:
                matched = True
                out += errors(props[key], item, root, f"{where}.{key}")
            for pattern, sub in schema.get("patternProperties", {}).items():
                if re.search(pattern, key):
                    matched = True
                    out += errors(sub, item, root, f"{where}.{key}")
            if not matched and "additionalProperties" in schema:
                out += errors(schema["additionalProperties"], item, root, f"{where}.{key}")
    if isinstance(value, list):
        prefix = schema.get("prefixItems", [])
        for k, item in enumerate(value):
            if k < len(prefix):
                out += errors(prefix[k], item, root, f"{where}[{k}]")
            elif "items" in schema:
                out += errors(schema["items"], item, root, f"{where}[{k}]")
        if len(value) < schema.get("minItems", 0):
            out.append(f"{where}: fewer than {schema['minItems']} items")
        if "maxItems" in schema and len(value) > schema["maxItems"]:
            out.append(f"{where}: more than {schema['maxItems']} items")
    if isinstance(value, str):
        if len(value) < schema.get("minLength", 0):
            out.append(f"{where}: shorter than {schema['minLength']}")
        if "pattern" in schema and not re.search(schema["pattern"], value):
            out.append(f"{where}: {value!r:.60} does not match {schema['pattern']}")
    if _is("number", value):
        if "minimum" in schema and value < schema["minimum"]:
            out.append(f"{where}: {value} < {schema['minimum']}")
        if "maximum" in schema and value > schema["maximum"]:
            out.append(f"{where}: {value} > {schema['maximum']}")
    if "allOf" in schema:
        for sub in schema["allOf"]:
            out += errors(sub, value, root, where)
    if "anyOf" in schema:
        found = [errors(sub, value, root, where) for sub in schema["anyOf"]]
        if all(found):
            out.append(f"{where}: matches none of anyOf ({min(found, key=len)[0]})")
    if "oneOf" in schema:
        found = [errors(sub, value, root, where) for sub in schema["oneOf"]]
        passing = sum(1 for f in found if not f)
        if passing != 1:
            out.append(f"{where}: matches {passing} of oneOf, not exactly 1"
                       + (f" ({min(found, key=len)[0]})" if passing == 0 else ""))
    if "not" in schema and not errors(schema["not"], value, root, where):
        out.append(f"{where}: matches what 'not' forbids")
    return out
