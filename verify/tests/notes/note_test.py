#!/usr/bin/env python3
"""A note of the corpus, checked from its claims file alone, against its independent derivation.

  note_test.py SIMPSON_VERIFY NOTE_DIR NAME

runs NAME.py (sympy: each claim's verdict, and the erratum a consequence follows from) and
`simpson-verify --paper NAME.tex --claims-file NAME.toml` (validation: the claims file records no
expected verdict), and fails, naming the claim, where the two differ or the note does not read.
"""
import json
import pathlib
import subprocess
import sys
import tempfile

binary, note_dir, name = sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3]
derived = json.loads(subprocess.run([sys.executable, str(note_dir / f"{name}.py")], check=True, capture_output=True, text=True).stdout)

with tempfile.TemporaryDirectory() as out:
    run = subprocess.run([binary, "--paper", str(note_dir / f"{name}.tex"), "--claims-file", str(note_dir / f"{name}.toml"),
                          "--no-certify", "--quiet", "--out", out], capture_output=True, text=True)
    if run.returncode not in (0, 1):
        print(f"FAIL {name}: simpson-verify exited {run.returncode}: {run.stderr.strip()}")
        sys.exit(1)
    report = json.loads((pathlib.Path(out) / "report.json").read_text())

failures = 0
seen = set()
for c in report["claims"]:
    seen.add(c["id"])
    want = derived.get(c["id"])
    if want is None:
        print(f"FAIL {name}: {c['id']}: no derivation in {name}.py")
        failures += 1
        continue
    got = {"verdict": c["verdict"], **({"follows_from": c["follows_from"]} if "follows_from" in c else {})}
    if got != want:
        print(f"FAIL {name}: {c['id']}: the harness says {got}, the derivation {want}\n     note: {c.get('note', '')[:300]}")
        failures += 1
for claim in sorted(set(derived) - seen):
    print(f"FAIL {name}: {claim}: derived but not in the report")
    failures += 1
print(f"{name}: {len(seen)} claims, {len(seen) - failures} as derived" if not failures else f"{name}: {failures} difference(s)")
sys.exit(1 if failures else 0)
