#!/usr/bin/env python3
"""Validates every preset, and the files `skinlayer material` writes, against app/material/material.schema.json
with python3-jsonschema (Debian python3-jsonschema); checks that the schema rejects what the reader rejects.

usage: validate_presets.py SCHEMA PRESETS_DIR SKINLAYER_EXECUTABLE
"""
import json
import pathlib
import subprocess
import sys

import jsonschema


def main() -> int:
    schema_path, presets_dir, skinlayer = sys.argv[1:4]
    schema = json.loads(pathlib.Path(schema_path).read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures = []

    presets = sorted(pathlib.Path(presets_dir).glob("*.json"))
    if len(presets) < 10:
        failures.append(f"only {len(presets)} presets in {presets_dir}")
    documents = {str(path): json.loads(path.read_text(encoding="utf-8")) for path in presets}
    # What `skinlayer material` writes: every value explicit, for a few materials (RGB, tau, lambert, matched).
    for flags in (["--preset", "skin-fair"], ["--tau", "0.3333", "--bottom", "lambert:0.4"],
                  ["--T", "0", "--bottom", "matched", "--ordinates", "48", "--model", "hk"],
                  ["--albedo", "0.9,0.5,0.25", "--bottom-sigma", "0.2", "--name", "x", "--description", "y"],
                  ["--skin", "melanin=0.1,blood=0.02", "--sigma", "0.35"]):
        written = subprocess.run([skinlayer, "material", *flags], check=True, capture_output=True, text=True)
        documents["skinlayer material " + " ".join(flags)] = json.loads(written.stdout)
    for name, document in documents.items():
        for error in validator.iter_errors(document):
            failures.append(f"{name}: {error.json_path}: {error.message}")

    # The schema must refuse what the reader refuses, or validating against it proves nothing.
    base = documents[str(presets[0])]
    refused = {
        "a key the reader does not know": {**base, "colour": 1},
        "g out of range": {**base, "layers": [{**base["layers"][0], "g": 1.2}]},
        "both T and tau": {**base, "layers": [{**base["layers"][0], "T": 0.5, "tau": 1}]},
        "a newer version": {**base, "version": 2},
        "an unknown bottom": {**base, "bottom": {"type": "wood"}},
        "two albedo channels": {**base, "layers": [{**base["layers"][0], "albedo": [1, 1]}]},
        "a skin with layers": {**base, "skin": {"melanin": 0.1}},
        "a skin out of range": {**{k: v for k, v in base.items() if k not in ("layers", "bottom")},
                                "skin": {"blood": 0.5}},
        "an unknown skin key": {**{k: v for k, v in base.items() if k not in ("layers", "bottom")},
                                "skin": {"freckles": 1}},
    }
    for what, document in refused.items():
        if validator.is_valid(document):
            failures.append(f"the schema accepts {what}")
    for failure in failures:
        print(failure, file=sys.stderr)
    print(f"{len(documents)} documents valid, {len(refused)} bad ones refused" if not failures else "FAILED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
