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

sys.dont_write_bytecode = True  # nothing written into the source tree

from verdicts import compare, report_of

binary, note_dir, name = sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3]
derived = json.loads(subprocess.run([sys.executable, str(note_dir / f"{name}.py")], check=True, capture_output=True, text=True).stdout)
report = report_of(binary, name, note_dir / f"{name}.tex", note_dir / f"{name}.toml")
got_of = lambda c: {"verdict": c["verdict"], **({"follows_from": c["follows_from"]} if "follows_from" in c else {})}
sys.exit(1 if compare(name, report, derived, got_of, f"the derivation in {name}.py") else 0)
