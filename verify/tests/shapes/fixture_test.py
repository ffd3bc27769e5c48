#!/usr/bin/env python3
"""A proof shape's fixture folder, run as a user runs a note: note.tex with its claims.toml.

  fixture_test.py SIMPSON_VERIFY FIXTURE_DIR

Each folder under verify/tests/shapes/ holds note.tex, a short document, and claims.toml, whose
every record states its `expected` verdict with its derivation by hand in a comment beside it. The
folder passes when `simpson-verify --paper note.tex --claims-file claims.toml` gives every record its
expected verdict. A folder must hold a statement the shape refuses (a verdict other than holds), so
that a shape that stopped telling right from wrong fails it.
"""
import json
import pathlib
import subprocess
import sys
import tempfile
import tomllib

binary, folder = sys.argv[1], pathlib.Path(sys.argv[2])
name = folder.name
records = tomllib.loads((folder / "claims.toml").read_text())["claim"]
expected = {}
for r in records:
    if "expected" not in r:
        sys.exit(f"FAIL {name}: record '{r['id']}' states no expected verdict")
    expected[r["id"]] = r["expected"]
if all(v == "holds" for v in expected.values()):
    sys.exit(f"FAIL {name}: every record holds; a fixture needs a statement its shape refuses")

with tempfile.TemporaryDirectory() as out:
    run = subprocess.run([binary, "--paper", str(folder / "note.tex"), "--claims-file", str(folder / "claims.toml"), "--no-certify",
                          "--quiet", "--out", out], capture_output=True, text=True)
    if run.returncode not in (0, 1):
        sys.exit(f"FAIL {name}: simpson-verify exited {run.returncode}: {run.stderr.strip()}")
    report = json.loads((pathlib.Path(out) / "report.json").read_text())

failures = 0
seen = set()
for c in report["claims"]:
    seen.add(c["id"])
    if c["verdict"] != expected.get(c["id"]):
        print(f"FAIL {name}: {c['id']}: verdict {c['verdict']}, expected {expected.get(c['id'])}\n     note: {c.get('note', '')[:300]}")
        failures += 1
for missing in sorted(set(expected) - seen):
    print(f"FAIL {name}: {missing}: not in the report")
    failures += 1
print(f"{name}: {len(seen)} claims as expected" if not failures else f"{name}: {failures} difference(s)")
sys.exit(1 if failures else 0)
