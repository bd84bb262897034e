#!/usr/bin/env python3
"""Validates JSON files against a JSON Schema (draft 2020-12) with the jsonschema package, an
implementation independent of the engine's loader.

    validate_json.py SCHEMA FILE...

Prints one line per file, in order: "valid", or "invalid POINTER: MESSAGE" (the first error by
JSON Schema's relevance order). Exits 2 when the schema itself is not a valid draft 2020-12 schema.
"""
import json
import sys

import jsonschema


def pointer(path):
    return "".join("/" + str(p).replace("~", "~0").replace("/", "~1") for p in path)


def main():
    with open(sys.argv[1], encoding="utf-8") as f:
        schema = json.load(f)
    try:
        jsonschema.Draft202012Validator.check_schema(schema)
    except jsonschema.exceptions.SchemaError as e:
        print(f"the schema is not a valid draft 2020-12 schema: {e.message}", file=sys.stderr)
        return 2
    validator = jsonschema.Draft202012Validator(schema)
    for name in sys.argv[2:]:
        with open(name, encoding="utf-8") as f:
            document = json.load(f)
        error = jsonschema.exceptions.best_match(validator.iter_errors(document))
        if error is None:
            print("valid")
        else:
            print(f"invalid {pointer(error.absolute_path)}: {error.message[:200]}".replace("\n", " "))
    return 0


if __name__ == "__main__":
    sys.exit(main())
