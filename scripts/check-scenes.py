#!/usr/bin/env python3
"""Validates every shipped scene (scenes/*.json) against scenes/scene.schema.json (docs/scenes.md).

Implements the subset of JSON Schema the schema uses (type, const, enum, required, properties,
additionalProperties: false, items, minItems/maxItems, minimum/maximum/exclusiveMinimum, minLength, oneOf, $ref
into $defs) with the standard library only. Also checks what a schema cannot: no key given twice in one object,
ids unique, springs and joints naming bodies, nesting within the loader's limit. Exit 0 when every scene passes, 1 listing each problem as FILE: PATH: message."""
import json
import os
import sys

TYPES = {"object": dict, "array": list, "string": str, "boolean": bool}


def type_ok(value, name):
    if name == "number":
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    if name == "integer":
        return isinstance(value, int) and not isinstance(value, bool)
    return isinstance(value, TYPES[name])


def validate(value, schema, root, path, problems):
    if "$ref" in schema:
        name = schema["$ref"].split("/")[-1]
        return validate(value, root["$defs"][name], root, path, problems)
    if "oneOf" in schema:
        fits = [alt for alt in schema["oneOf"] if not validate_quiet(value, alt, root)]
        if len(fits) != 1:
            problems.append(f"{path}: must match exactly one of {len(schema['oneOf'])} forms (got {json.dumps(value)})")
            return
        return validate(value, fits[0], root, path, problems)
    if "type" in schema and not type_ok(value, schema["type"]):
        problems.append(f"{path}: must be of type {schema['type']} (got {json.dumps(value)})")
        return
    if "const" in schema and value != schema["const"]:
        problems.append(f"{path}: must be {schema['const']} (got {json.dumps(value)})")
    if "enum" in schema and value not in schema["enum"]:
        problems.append(f"{path}: must be one of {schema['enum']} (got {json.dumps(value)})")
    if "minimum" in schema and value < schema["minimum"]:
        problems.append(f"{path}: must be >= {schema['minimum']} (got {value})")
    if "maximum" in schema and value > schema["maximum"]:
        problems.append(f"{path}: must be <= {schema['maximum']} (got {value})")
    if "exclusiveMinimum" in schema and not value > schema["exclusiveMinimum"]:
        problems.append(f"{path}: must be > {schema['exclusiveMinimum']} (got {value})")
    if "minLength" in schema and len(value) < schema["minLength"]:
        problems.append(f"{path}: must have at least {schema['minLength']} characters")
    if isinstance(value, list):
        if len(value) < schema.get("minItems", 0) or len(value) > schema.get("maxItems", len(value)):
            problems.append(f"{path}: wrong number of entries ({len(value)})")
        for i, item in enumerate(value):
            if "items" in schema:
                validate(item, schema["items"], root, f"{path}[{i}]", problems)
    if isinstance(value, dict):
        props = schema.get("properties", {})
        for key in schema.get("required", []):
            if key not in value:
                problems.append(f"{path}.{key}: is required".lstrip("."))
        for key, item in value.items():
            where = f"{path}.{key}".lstrip(".")
            if key in props:
                validate(item, props[key], root, where, problems)
            elif schema.get("additionalProperties") is False:
                problems.append(f"{where}: unknown key")


def validate_quiet(value, schema, root):
    problems = []
    validate(value, schema, root, "", problems)
    return problems


class DuplicateKey(ValueError):
    pass


def unique_keys(pairs):
    """object_pairs_hook: json keeps the last of a key given twice; a scene file refuses it (docs/scenes.md)."""
    seen = {}
    for key, value in pairs:
        if key in seen:
            raise DuplicateKey(f"duplicate key {key!r}")
        seen[key] = value
    return seen


MAX_NESTING = 64  # SceneLimits::kMaxNesting (docs/scenes.md, "Limits")


def nesting(text):
    """Deepest level of [ and { outside strings, as the loader measures it before parsing (JsonNesting.h)."""
    depth = deepest = 0
    in_string = escaped = False
    for c in text:
        if in_string:
            if escaped:
                escaped = False
            elif c == "\\":
                escaped = True
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
        elif c in "[{":
            depth += 1
            deepest = max(deepest, depth)
        elif c in "]}" and depth > 0:
            depth -= 1
    return deepest


def check_ids(scene, problems):
    ids = set()
    for i, body in enumerate(scene.get("bodies", [])):
        if body.get("id") in ids:
            problems.append(f"bodies[{i}].id: duplicate id {body.get('id')!r}")
        ids.add(body.get("id"))
    for kind in ("springs", "joints"):
        for i, link in enumerate(scene.get(kind, [])):
            for end in ("a", "b"):
                if link.get(end) not in ids:
                    problems.append(f"{kind}[{i}].{end}: names no body ({link.get(end)!r})")


def main():
    root_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    scenes = os.path.join(root_dir, "scenes")
    with open(os.path.join(scenes, "scene.schema.json"), encoding="utf-8") as f:
        schema = json.load(f)
    failures = 0
    names = sorted(n for n in os.listdir(scenes) if n.endswith(".json") and n != "scene.schema.json")
    if not names:
        print("check-scenes: no scenes in", scenes)
        return 1
    for name in names:
        problems = []
        with open(os.path.join(scenes, name), encoding="utf-8") as f:
            text = f.read()
        scene = None
        depth = nesting(text)
        if depth > MAX_NESTING:
            problems.append(f"arrays and objects nest {depth} levels deep, over the limit of {MAX_NESTING}")
        else:
            try:
                scene = json.loads(text, object_pairs_hook=unique_keys)
            except DuplicateKey as e:
                problems.append(str(e))
        if scene is not None:
            validate(scene, schema, schema, "", problems)
            check_ids(scene, problems)
        for p in problems:
            print(f"scenes/{name}: {p}")
        failures += bool(problems)
    print(f"check-scenes: {len(names)} scenes, {failures} failing")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
